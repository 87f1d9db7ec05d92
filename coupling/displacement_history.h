#pragma once
// The displacement history of one probe point (e.g. the elastic gate's free end):
// time, dx, dy. Written by coupled runs (CSV: time_s, dx_m, dy_m), read back by
// `chipflex plot`, and compared with the experiment by RMS error at the experiment's
// frames, with the model curve interpolated linearly — the definition under which the
// published errors of data/antoci2007/README.md were computed.

#include <string>
#include <vector>

namespace chipflex::coupling
{
class DisplacementHistory
{
public:
  struct Errors
  {
    double rms_dx = 0; ///< m
    double rms_dy = 0; ///< m
    int frames = 0;    ///< reference frames inside the window
  };

  void append(double time, double dx, double dy);
  std::size_t size() const { return time_.size(); }
  bool empty() const { return time_.empty(); }
  const std::vector<double>& time() const { return time_; }
  const std::vector<double>& dx() const { return dx_; }
  const std::vector<double>& dy() const { return dy_; }
  /// Drops every sample later than `time` (a restarted run continues from there).
  void truncate_after(double time);

  /// Linear interpolation; `component` 0 = dx, 1 = dy. Throws InputError outside the
  /// recorded interval (no extrapolation: a short run must not look like a good one).
  double interpolate(double time, int component) const;

  /// RMS of (this - reference) over the reference's frames with t0 <= t <= t1. A
  /// frame outside this history is an error, unless `skip_uncovered` (used for the
  /// published curves, some of which end before 0.36 s: the README's figures skip
  /// those frames).
  Errors rms_error(const DisplacementHistory& reference, double t0, double t1,
                   bool skip_uncovered = false) const;

  /// Writes `time_s,dx_m,dy_m` atomically.
  void write_csv(const std::string& path) const;
  /// Reads a CSV with '#' comment lines and one header line. Either three columns
  /// (time, dx, dy) or, with `single_component` = 0 or 1, two columns (time, value)
  /// stored as dx or dy (the published curves come one component per file).
  static DisplacementHistory read_csv(const std::string& path, int single_component = -1);

private:
  std::vector<double> time_, dx_, dy_;
};
} // namespace chipflex::coupling
