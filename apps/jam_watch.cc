#include "apps/jam_watch.h"

#include "common/hdf5_file.h"
#include "common/input_error.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace chipflex::apps
{
namespace
{
/// The column whose name starts with `prefix` (a gauge's column carries its unit after
/// the name, e.g. q_barrier_m2_s in 2D, q_barrier_m3_s in 3D).
std::size_t column_of(const std::vector<std::string>& columns, const std::string& prefix,
                      const std::string& key, const std::string& gauge)
{
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i].rfind(prefix, 0) == 0)
      return i;
  throw InputError("probes/jam watch/" + key,
                   "'" + gauge + "' names no gauge of the case (its probes give " +
                       std::to_string(columns.size()) + " columns; add it under probes/" +
                       (key == "pressure gauge" ? "pressure" : "flow rate") + ")");
}
} // namespace

JamWatch::JamWatch(const JamWatchSettings& settings, const std::vector<std::string>& columns)
    : settings_(settings)
{
  if (!settings.pressure_gauge.empty())
  {
    Signal s;
    s.column = "p_" + settings.pressure_gauge + "_Pa";
    s.index = column_of(columns, s.column, "pressure gauge", settings.pressure_gauge);
    s.rising = true;
    s.threshold = settings.pressure_factor;
    s.reference = settings.reference_pressure;
    s.measured = std::isnan(s.reference);
    signals_.push_back(s);
  }
  if (!settings.flow_gauge.empty())
  {
    Signal s;
    s.index =
        column_of(columns, "q_" + settings.flow_gauge + "_m", "flow gauge", settings.flow_gauge);
    s.column = columns[s.index];
    s.rising = false;
    s.threshold = settings.flow_fraction;
    s.reference = settings.reference_flow;
    s.measured = std::isnan(s.reference);
    signals_.push_back(s);
  }
  samples_.resize(signals_.size());
}

double JamWatch::running_mean(std::size_t k) const
{
  double sum = 0;
  for (double v : samples_[k])
    sum += v;
  return samples_[k].empty() ? 0 : sum / double(samples_[k].size());
}

std::string JamWatch::update(double time, const std::vector<double>& row)
{
  std::ostringstream log;
  log.precision(4);
  for (auto& s : signals_)
  {
    if (!std::isnan(s.reference))
      continue;
    if (time >= settings_.reference_start && time <= settings_.reference_end)
    {
      s.reference_sum += row[s.index];
      ++s.reference_count;
    }
    else if (time > settings_.reference_end)
    {
      // The window has passed: its mean is the unblocked flow's value. A reference that
      // is not positive (a gauge in a wake, the flow reversed) cannot be scaled by a
      // factor: that criterion is off, and the log says why.
      s.reference = s.reference_count > 0 ? s.reference_sum / double(s.reference_count) : 0;
      if (!(s.reference > 0))
      {
        log << (log.tellp() > 0 ? "\n" : "") << "warning: jam watch: " << s.column
            << " has the reference " << s.reference << " over " << settings_.reference_start
            << " ... " << settings_.reference_end << " s (" << s.reference_count
            << " probe rows); a jam criterion needs a positive one, so "
            << "this one is off";
        s.reference = 0;
      }
    }
  }

  // The running mean over the last `averaging time` of probe rows after the start-up.
  if (time < settings_.start_time)
    return log.str();
  sample_times_.push_back(time);
  for (std::size_t k = 0; k < signals_.size(); ++k)
    samples_[k].push_back(row[signals_[k].index]);
  std::size_t old = 0;
  while (old < sample_times_.size() && sample_times_[old] <= time - settings_.averaging_time)
    ++old;
  if (old > 0)
  {
    sample_times_.erase(sample_times_.begin(), sample_times_.begin() + long(old));
    for (auto& v : samples_)
      v.erase(v.begin(), v.begin() + long(old));
  }

  // Each gauge is compared once its mean covers a whole averaging time of rows after the
  // start-up and, for a measured reference, after the reference window.
  for (std::size_t k = 0; k < signals_.size(); ++k)
  {
    auto& s = signals_[k];
    const double ready =
        std::max(settings_.start_time, s.measured ? settings_.reference_end : 0.0) +
        settings_.averaging_time;
    if (!(s.reference > 0) || time < ready * (1 - 1e-12))
      continue;
    const double ratio = running_mean(k) / s.reference;
    if (std::isnan(s.extreme_ratio) ||
        (s.rising ? ratio > s.extreme_ratio : ratio < s.extreme_ratio))
      s.extreme_ratio = ratio;
    const bool met = s.rising ? ratio >= s.threshold : ratio <= s.threshold;
    if (met && !jammed())
    {
      jam_time_ = time;
      std::ostringstream cause;
      cause.precision(4);
      cause << s.column << " " << settings_.averaging_time << " s mean " << running_mean(k) << " = "
            << ratio << " x its reference " << s.reference << " ("
            << (s.rising ? "limit >= " : "limit <= ") << s.threshold << ")";
      jam_cause_ = cause.str();
      log << (log.tellp() > 0 ? "\n" : "") << "jam: at t = " << time << " s: " << jam_cause_;
    }
  }
  return log.str();
}

std::string JamWatch::summary_line() const
{
  std::ostringstream s;
  s.precision(6);
  s << "jam:";
  for (const auto& g : signals_)
    s << " " << g.column << "_reference=" << g.reference << " " << g.column
      << (g.rising ? "_largest_ratio=" : "_smallest_ratio=") << g.extreme_ratio;
  s << " pressure_factor=" << settings_.pressure_factor
    << " flow_fraction=" << settings_.flow_fraction << " averaging_s=" << settings_.averaging_time
    << " jammed=" << (jammed() ? "yes" : "no");
  if (jammed())
    s << " time_to_jam_s=" << jam_time_ << " cause=\"" << jam_cause_ << "\"";
  return s.str();
}

void JamWatch::save(Hdf5File& file, const std::string& group) const
{
  // One flat record: the jam, each signal's reference state, then the running window.
  std::vector<double> state = {jam_time_, double(signals_.size()), double(sample_times_.size())};
  for (const auto& s : signals_)
    state.insert(state.end(),
                 {s.reference, s.reference_sum, double(s.reference_count), s.extreme_ratio});
  for (std::size_t i = 0; i < sample_times_.size(); ++i)
  {
    state.push_back(sample_times_[i]);
    for (const auto& v : samples_)
      state.push_back(v[i]);
  }
  file.write(group + "/jam_watch", state, {state.size()});
  // One trailing blank keeps the string non-empty before the jam (an empty HDF5 string).
  file.write(group + "/jam_watch_cause", std::vector<std::string>{jam_cause_ + " "});
}

void JamWatch::load(const Hdf5File& file, const std::string& group)
{
  const std::vector<double> state = file.read_doubles(group + "/jam_watch");
  const std::size_t n_signals = state.size() >= 3 ? std::size_t(state[1]) : 0;
  const std::size_t n_samples = state.size() >= 3 ? std::size_t(state[2]) : 0;
  if (n_signals != signals_.size() ||
      state.size() != 3 + 4 * n_signals + n_samples * (1 + n_signals))
    throw InputError(file.path() + ": " + group + "/jam_watch",
                     "the checkpoint's jam watch does not match the case's (" +
                         std::to_string(n_signals) + " gauges against " +
                         std::to_string(signals_.size()) + ")");
  jam_time_ = state[0];
  std::size_t i = 3;
  for (auto& s : signals_)
  {
    s.reference = state[i++];
    s.reference_sum = state[i++];
    s.reference_count = long(state[i++]);
    s.extreme_ratio = state[i++];
  }
  sample_times_.clear();
  for (auto& v : samples_)
    v.clear();
  for (std::size_t k = 0; k < n_samples; ++k)
  {
    sample_times_.push_back(state[i++]);
    for (auto& v : samples_)
      v.push_back(state[i++]);
  }
  jam_cause_ = file.read_strings(group + "/jam_watch_cause").at(0);
  jam_cause_.pop_back();
}
} // namespace chipflex::apps
