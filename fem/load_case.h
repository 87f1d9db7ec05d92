#pragma once
// Named load patterns on physical groups, for static correction modes and `compare`:
//   pressure:GROUP          unit pressure (1 Pa) on the group's faces, acting inward
//   force:GROUP:fx,fy[,fz]  a total force (N; 2D: N per metre of depth) spread as a
//                           uniform traction over the group's faces

#include <string>
#include <vector>

namespace chipflex::fem
{
struct LoadCase
{
  enum class Kind
  {
    pressure,
    force
  };
  std::string text; ///< as given, e.g. "force:tip:0,-1"
  Kind kind = Kind::pressure;
  std::string group;
  std::vector<double> force; ///< Kind::force: dim entries

  /// Throws InputError(option, ...) for a malformed text or a force with != dim entries.
  static LoadCase parse(const std::string& text, int dim, const std::string& option);
};
} // namespace chipflex::fem
