#pragma once
// Watches an internal flow for tearing. A channel with an inlet and an outlet holds a
// fixed volume of fluid: in a steady or periodic flow the number of fluid particles in
// the domain stays about constant. When weakly-compressible SPH cannot hold a wake full
// (suction behind a body, no ambient pressure), a void opens and the outlet takes out
// more than the inlet brings, so the count falls. Such a run can finish with no particle
// lost and a plausible-looking body motion in an emptied channel: this check makes it say
// so, once in the log when the count first falls more than the case's fraction below its
// start, and in summary.txt (docs/output.md, "summary.txt"). Under a background pressure
// P the count can also fall without a void, the particles thinning evenly: P then pushes
// the fluid away from the buffers' denser lattice, and the gauge pressures shift by about
// 2 P times the drop (docs/sph.md, "What the background pressure costs"); the warning
// gives that figure.

#include <cstddef>
#include <cstdint>
#include <string>

namespace chipflex
{
class Hdf5File;
}

namespace chipflex::apps
{
class FluidContinuityCheck
{
public:
  /// `warning_fraction`: the drop below the starting count (0.05 = 5 %) that counts as
  /// tearing; >= 1 switches the warning off (a tank that drains on purpose).
  /// `background_pressure` (Pa): the fluid's, for the warning's estimate of what an even
  /// thinning does to the gauge pressures.
  explicit FluidContinuityCheck(double warning_fraction, double background_pressure = 0)
      : warning_fraction_(warning_fraction), background_pressure_(background_pressure)
  {
  }

  /// After a step: the fluid particles now in the domain. Returns a log line the first
  /// time the drop passes the warning fraction, "" otherwise.
  std::string update(double time, std::size_t n_fluid);

  bool torn() const { return warned_; }
  /// The number of fluid particles at the run's start (restored from a checkpoint).
  std::size_t start() const { return start_; }
  /// One summary.txt line: start, smallest and last count, the largest drop and whether
  /// it passed the warning fraction.
  std::string summary_line() const;

  /// The check's state in the checkpoint's /run group (a restart warns once, too).
  void save(Hdf5File& file, const std::string& group) const;
  void load(const Hdf5File& file, const std::string& group);

private:
  double drop(std::size_t n) const { return start_ > 0 ? 1.0 - double(n) / double(start_) : 0; }

  double warning_fraction_, background_pressure_;
  std::size_t start_ = 0, smallest_ = 0, last_ = 0;
  double smallest_time_ = 0;
  bool started_ = false, warned_ = false;
};
} // namespace chipflex::apps
