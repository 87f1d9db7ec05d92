#include "apps/progress_meter.h"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace chipflex::apps
{
ProgressMeter::ProgressMeter(double start_time, double end_time, double line_interval)
    : start_time_(start_time), end_time_(end_time), line_interval_(line_interval),
      terminal_(isatty(STDERR_FILENO)), started_(Clock::now()), last_print_(started_)
{
}

void ProgressMeter::update(double time, std::int64_t step, bool force)
{
  if (first_step_ < 0)
    first_step_ = step;
  const auto now = Clock::now();
  const double since = std::chrono::duration<double>(now - last_print_).count();
  if (force || since >= (terminal_ ? 0.25 : line_interval_))
  {
    print(time, step, false);
    last_print_ = now;
  }
}

void ProgressMeter::finish(double time, std::int64_t step)
{
  print(time, step, true);
}

void ProgressMeter::print(double time, std::int64_t step, bool final)
{
  const double wall = std::chrono::duration<double>(Clock::now() - started_).count();
  const double done = std::clamp((time - start_time_) / (end_time_ - start_time_), 0.0, 1.0);
  const double steps_per_s =
      wall > 0 ? double(step - std::max<std::int64_t>(first_step_, 0)) / wall : 0;
  const double eta = done > 0 ? wall * (1 - done) / done : 0;
  if (terminal_)
  {
    const int width = 30, filled = int(done * width);
    std::fprintf(stderr, "\r[%.*s%*s] %5.1f%%  t = %.4g s  %.0f steps/s  ETA %.0f s   ", filled,
                 "##############################", width - filled, "", 100 * done, time,
                 steps_per_s, eta);
    if (final)
      std::fprintf(stderr, "\n");
  }
  else
    std::fprintf(stderr, "t = %.6g s (%.1f%%), step %lld, %.0f steps/s, ETA %.0f s\n", time,
                 100 * done, static_cast<long long>(step), steps_per_s, eta);
  std::fflush(stderr);
}
} // namespace chipflex::apps
