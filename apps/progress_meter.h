#pragma once
// Progress of a run on stderr: on a terminal a bar redrawn in place with simulated
// time, steps/s and the estimated time left; otherwise (logs, pipes) a plain line every
// `line_interval` seconds of wall time.

#include <chrono>
#include <cstdint>

namespace chipflex::apps
{
class ProgressMeter
{
public:
  ProgressMeter(double start_time, double end_time, double line_interval = 10);
  void update(double time, std::int64_t step, bool force = false);
  void finish(double time, std::int64_t step);

private:
  using Clock = std::chrono::steady_clock;
  void print(double time, std::int64_t step, bool final);
  double start_time_, end_time_, line_interval_;
  bool terminal_;
  Clock::time_point started_, last_print_;
  std::int64_t first_step_ = -1;
};
} // namespace chipflex::apps
