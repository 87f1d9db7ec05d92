// `subsection probes` of a case file (apps/case_file.h): pressure, water-height and
// flow-rate gauges (probes.csv).

#include "apps/probe_case_keys.h"

#include "apps/case_values.h"
#include "common/input_error.h"

#include <deal.II/base/parameter_handler.h>

namespace chipflex::apps
{
using dealii::ParameterHandler;
using dealii::Patterns::Anything;
using dealii::Patterns::Bool;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;

namespace
{
template <int dim>
std::vector<sph::Probe<dim>> probes_of(const std::string& key, const std::string& text)
{
  std::vector<sph::Probe<dim>> out;
  for (const auto& item : split(text, ';'))
  {
    const auto colon = item.find(':');
    if (colon == std::string::npos || trim(item.substr(0, colon)).empty())
      throw InputError(key, "'" + item + "' is not 'name: x, y" + (dim == 3 ? ", z'" : "'"));
    const std::string name = trim(item.substr(0, colon));
    if (name.find_first_of(" ,\"") != std::string::npos)
      throw InputError(key, "probe name '" + name + "' must not contain spaces, commas or quotes");
    out.push_back({name, vector_of<dim>(key, item.substr(colon + 1))});
  }
  return out;
}

template <int dim>
std::vector<sph::FlowSection> sections_of(const std::string& key, const std::string& text)
{
  std::vector<sph::FlowSection> out;
  const std::string numbers_form = dim == 2 ? "x0, y0, x1, y1" : "x, y, z, nx, ny, nz";
  const std::string form = "'name: " + numbers_form + "'";
  for (const auto& item : split(text, ';'))
  {
    const auto colon = item.find(':');
    if (colon == std::string::npos || trim(item.substr(0, colon)).empty())
      throw InputError(key, "'" + item + "' is not " + form);
    const std::string name = trim(item.substr(0, colon));
    if (name.find_first_of(" ,\"") != std::string::npos)
      throw InputError(key, "gauge name '" + name + "' must not contain spaces, commas or quotes");
    const auto v = numbers(key, item.substr(colon + 1));
    if (v.size() != 2 * std::size_t(dim))
      throw InputError(key, "'" + item + "' needs " + std::to_string(2 * dim) +
                                " numbers: " + numbers_form);
    sph::FlowSection section;
    section.name = name;
    if constexpr (dim == 2)
    {
      section.a = Eigen::Vector2d(v[0], v[1]);
      section.b = Eigen::Vector2d(v[2], v[3]);
      if (!((section.b - section.a).norm() > 0))
        throw InputError(key, "'" + item + "': the section has zero length");
    }
    else
    {
      section.point = Eigen::Vector3d(v[0], v[1], v[2]);
      section.normal = Eigen::Vector3d(v[3], v[4], v[5]);
      if (!(section.normal.norm() > 0))
        throw InputError(key, "'" + item + "': the normal is zero");
      section.normal.normalize();
    }
    out.push_back(section);
  }
  return out;
}
} // namespace

void declare_probe_keys(ParameterHandler& prm)
{
  prm.enter_subsection("probes");
  prm.declare_entry("pressure", "", Anything(),
                    "Pressure gauges 'name: x, y[, z]' (m), separated by ';' -> p_<name>_Pa.");
  prm.declare_entry("water height", "", Anything(),
                    "Water-height gauges 'name: x, y[, z]' (m; the vertical coordinate is "
                    "ignored), separated by ';' -> h_<name>_m (surface elevation).");
  prm.declare_entry("flow rate", "", Anything(),
                    "Flow-rate gauges, separated by ';'. 2D: 'name: x0, y0, x1, y1' (m, the "
                    "section from (x0, y0) to (x1, y1)) -> q_<name>_m2_s (volume flow, m^2/s "
                    "per metre of depth, positive to the right of the section's direction). "
                    "3D: 'name: x, y, z, nx, ny, nz' (the whole plane through the point, "
                    "normal n) -> q_<name>_m3_s (m^3/s, positive along n).");
  prm.leave_subsection();
}

template <int dim>
void read_probe_keys(ParameterHandler& prm, sph::CaseDescription<dim>& c)
{
  prm.enter_subsection("probes");
  c.pressure_probes = probes_of<dim>("probes/pressure", prm.get("pressure"));
  c.height_probes = probes_of<dim>("probes/water height", prm.get("water height"));
  c.flow_sections = sections_of<dim>("probes/flow rate", prm.get("flow rate"));
  prm.leave_subsection();
}

template void read_probe_keys(ParameterHandler&, sph::CaseDescription<2>&);
template void read_probe_keys(ParameterHandler&, sph::CaseDescription<3>&);
} // namespace chipflex::apps
