#include "coupling/displacement_history.h"

#include "common/atomic_output.h"
#include "common/input_error.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace chipflex::coupling
{
void DisplacementHistory::append(double time, double dx, double dy)
{
  if (!time_.empty() && time < time_.back())
    throw std::logic_error("DisplacementHistory: samples must come in time order");
  time_.push_back(time);
  dx_.push_back(dx);
  dy_.push_back(dy);
}

void DisplacementHistory::truncate_after(double time)
{
  const auto n = std::upper_bound(time_.begin(), time_.end(), time) - time_.begin();
  time_.resize(n);
  dx_.resize(n);
  dy_.resize(n);
}

double DisplacementHistory::interpolate(double time, int component) const
{
  const auto& y = component == 0 ? dx_ : dy_;
  // A small tolerance: output times are sums of time steps and may miss a frame by
  // round-off.
  const double tol = 1e-9;
  if (time_.empty() || time < time_.front() - tol || time > time_.back() + tol)
  {
    std::ostringstream s;
    s << "time " << time << " s outside the recorded history ["
      << (time_.empty() ? 0.0 : time_.front()) << ", " << (time_.empty() ? 0.0 : time_.back())
      << "] s";
    throw InputError("displacement history", s.str());
  }
  if (time_.size() == 1)
    return y.front();
  auto hi = std::lower_bound(time_.begin(), time_.end(), time) - time_.begin();
  hi = std::clamp<long>(hi, 1, static_cast<long>(time_.size()) - 1);
  const long lo = hi - 1;
  const double span = time_[hi] - time_[lo];
  if (span <= 0)
    return y[hi];
  const double s = (time - time_[lo]) / span;
  return (1 - s) * y[lo] + s * y[hi];
}

DisplacementHistory::Errors DisplacementHistory::rms_error(const DisplacementHistory& reference,
                                                           double t0, double t1,
                                                           bool skip_uncovered) const
{
  Errors e;
  double sx = 0, sy = 0;
  for (std::size_t i = 0; i < reference.size(); ++i)
  {
    const double t = reference.time_[i];
    if (t < t0 - 1e-9 || t > t1 + 1e-9)
      continue;
    if (skip_uncovered && (empty() || t < time_.front() || t > time_.back()))
      continue;
    const double ex = interpolate(t, 0) - reference.dx_[i];
    const double ey = interpolate(t, 1) - reference.dy_[i];
    sx += ex * ex;
    sy += ey * ey;
    ++e.frames;
  }
  if (e.frames == 0)
    throw InputError("displacement history", "no reference frame inside the error window");
  e.rms_dx = std::sqrt(sx / e.frames);
  e.rms_dy = std::sqrt(sy / e.frames);
  return e;
}

void DisplacementHistory::write_csv(const std::string& path) const
{
  AtomicOutput output(path);
  {
    std::ofstream out(output.temporary_path());
    if (!out)
      throw InputError(path, "cannot write");
    out << "time_s,dx_m,dy_m\n" << std::setprecision(10);
    for (std::size_t i = 0; i < time_.size(); ++i)
      out << time_[i] << ',' << dx_[i] << ',' << dy_[i] << '\n';
    if (!out)
      throw InputError(path, "write failed");
  }
  output.commit();
}

DisplacementHistory DisplacementHistory::read_csv(const std::string& path, int single_component)
{
  std::ifstream in(path);
  if (!in)
    throw InputError(path, "cannot open");
  DisplacementHistory h;
  const std::size_t columns = single_component < 0 ? 3 : 2;
  std::string line;
  bool header_seen = false;
  int line_number = 0;
  while (std::getline(in, line))
  {
    ++line_number;
    if (line.empty() || line[0] == '#')
      continue;
    if (!header_seen)
    {
      header_seen = true; // e.g. "time_s,dx_m,dy_m"
      continue;
    }
    std::vector<double> values;
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ','))
    {
      try
      {
        std::size_t used = 0;
        values.push_back(std::stod(cell, &used));
      }
      catch (const std::exception&)
      {
        throw InputError(path + ":" + std::to_string(line_number),
                         "'" + cell + "' is not a number");
      }
    }
    if (values.size() != columns)
      throw InputError(path + ":" + std::to_string(line_number),
                       "expected " + std::to_string(columns) + " columns, found " +
                           std::to_string(values.size()));
    if (!h.time_.empty() && values[0] < h.time_.back())
      throw InputError(path + ":" + std::to_string(line_number), "time goes backwards");
    if (columns == 3)
      h.append(values[0], values[1], values[2]);
    else if (single_component == 0)
      h.append(values[0], values[1], 0.0);
    else
      h.append(values[0], 0.0, values[1]);
  }
  if (h.empty())
    throw InputError(path, "no data rows");
  return h;
}
} // namespace chipflex::coupling
