#include "apps/channel_acoustics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace chipflex::apps
{
template <int dim>
double channel_length(const sph::CaseDescription<dim>& c)
{
  if (c.open_boundaries.empty())
    return 0;
  const int axis = c.open_boundaries.front().axis;
  double inlet = std::numeric_limits<double>::quiet_NaN(), outlet = inlet;
  for (const auto& z : c.open_boundaries)
    if (z.axis == axis)
      (z.kind == sph::OpenBoundaryKind::inlet ? inlet : outlet) = z.plane();
  if (std::isfinite(inlet) && std::isfinite(outlet))
    return std::abs(outlet - inlet);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& b : c.fluid_blocks)
  {
    lo = std::min(lo, b.min[axis]);
    hi = std::max(hi, b.max[axis]);
  }
  return hi > lo ? hi - lo : 0;
}

std::vector<std::string>
acoustic_warnings(double speed_of_sound, double length,
                  const std::vector<std::pair<std::string, double>>& frequencies)
{
  std::vector<std::string> lines;
  if (!(length > 0 && speed_of_sound > 0))
    return lines;
  const double acoustic = speed_of_sound / (4 * length);
  for (const auto& [name, f] : frequencies)
  {
    if (!(f > 0) || f > 3 * acoustic || f < acoustic / 3)
      continue;
    std::ostringstream s;
    s.precision(4);
    s << "warning: the channel's acoustic frequency c0 / (4 L) = " << acoustic
      << " Hz (c0 = " << speed_of_sound << " m/s, L = " << length << " m) lies within a factor "
      << "of 3 of " << name << ", " << f << " Hz: its ringing can drive the flow and the bodies. "
      << "Raise c0 to at least " << 12 * length * f
      << " m/s (3 times the frequency; the time step shrinks as 1/c0) or see docs/sph.md, "
         "\"Choosing c0 for channels\"";
    lines.push_back(s.str());
  }
  return lines;
}

template double channel_length(const sph::CaseDescription<2>&);
template double channel_length(const sph::CaseDescription<3>&);
} // namespace chipflex::apps
