#pragma once
// Watches a flow for a jam: bodies (chips) that block a channel raise the pressure in
// front of them and cut the flow through it. The watch compares a pressure gauge's and
// a flow-rate gauge's running means with their values in the unblocked flow (given,
// or measured over a reference window early in the run) and reports the first time
// the pressure reaches `pressure factor` times its reference or the flow falls to
// `flow fraction` of its reference: the time to jam. It says so once in the log and in
// summary.txt's `jam:` line (docs/output.md), and its state is part of the checkpoint.
// It reads the probe rows only, so it costs nothing between probe times.

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace chipflex
{
class Hdf5File;
}

namespace chipflex::apps
{
/// `probes/jam watch` of a case file (apps/probe_case_keys.cc documents each key).
struct JamWatchSettings
{
  std::string pressure_gauge; ///< a pressure gauge's name; "" = no pressure criterion
  double pressure_factor = 2;
  std::string flow_gauge; ///< a flow-rate gauge's name; "" = no flow criterion
  double flow_fraction = 0.5;
  /// The unblocked flow's values; NaN: measured as the mean over the reference window.
  double reference_pressure = std::numeric_limits<double>::quiet_NaN();
  double reference_flow = std::numeric_limits<double>::quiet_NaN();
  double reference_start = 0, reference_end = 0; ///< s
  double averaging_time = 0.002;                 ///< s, the running mean's length
  double start_time = 0; ///< s: probe rows before it (the start-up) are not watched
  /// s: end the run this long after the jam (a study of the time to jam needs no more,
  /// and a flow-fed channel closed by a jam only compresses further); < 0: run on.
  double stop_after = -1;

  bool enabled() const { return !pressure_gauge.empty() || !flow_gauge.empty(); }
};

class JamWatch
{
public:
  /// `columns`: the probe row's column names (probes.csv's header, without time); the
  /// gauges must be among them (InputError otherwise).
  JamWatch(const JamWatchSettings& settings, const std::vector<std::string>& columns);

  /// At a probe time: the probe row. Returns a log line when the jam is first seen, or
  /// when a measured reference cannot serve (not positive), "" otherwise.
  std::string update(double time, const std::vector<double>& row);

  bool jammed() const { return jam_time_ >= 0; }
  double time_to_jam() const { return jam_time_; }
  /// True once the run has gone on `stop after` past the jam.
  bool run_done(double time) const
  {
    return jammed() && settings_.stop_after >= 0 && time >= jam_time_ + settings_.stop_after;
  }
  /// One summary.txt line: the criterion, the references, jammed=yes|no, the time to jam
  /// and the largest pressure ratio / smallest flow ratio the running means reached.
  std::string summary_line() const;

  void save(Hdf5File& file, const std::string& group) const;
  void load(const Hdf5File& file, const std::string& group);

private:
  /// One watched gauge: its column, reference and running mean.
  struct Signal
  {
    std::string column;
    bool rising = true; ///< pressure: jam when the mean rises to factor x reference
    double threshold = 2;
    double reference = std::numeric_limits<double>::quiet_NaN();
    bool measured = false; ///< the reference is the reference window's mean
    double reference_sum = 0;
    long reference_count = 0;
    std::size_t index = 0;
    double extreme_ratio = std::numeric_limits<double>::quiet_NaN();
  };
  double running_mean(std::size_t k) const;

  JamWatchSettings settings_;
  std::vector<Signal> signals_;
  std::vector<double> sample_times_;
  std::vector<std::vector<double>> samples_; ///< per signal, aligned with sample_times_
  double jam_time_ = -1;
  std::string jam_cause_;
};
} // namespace chipflex::apps
