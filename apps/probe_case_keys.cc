// `subsection probes` of a case file (apps/case_file.h): pressure, water-height and
// flow-rate gauges (probes.csv), and the jam watch that reads them.

#include "apps/probe_case_keys.h"

#include "apps/case_values.h"
#include "common/input_error.h"

#include <cmath>
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
  // The jam watch (apps/jam_watch.h, docs/output.md "The jam watch").
  prm.enter_subsection("jam watch");
  prm.declare_entry("pressure gauge", "", Anything(),
                    "A pressure gauge's name (probes/pressure), e.g. the one in front of where "
                    "bodies can block the flow: the run reports a jam when its running mean "
                    "reaches `pressure factor` times its reference. Empty: no pressure "
                    "criterion.");
  prm.declare_entry("pressure factor", "2", Double(1),
                    "The pressure criterion: the running mean over its reference at a jam, -.");
  prm.declare_entry("flow gauge", "", Anything(),
                    "A flow-rate gauge's name (probes/flow rate), e.g. a section behind the "
                    "blockage: a jam when its running mean falls to `flow fraction` of its "
                    "reference. Empty: no flow criterion.");
  prm.declare_entry("flow fraction", "0.5", Double(0, 1),
                    "The flow criterion: the running mean over its reference at a jam, -.");
  prm.declare_entry("reference pressure", "", Anything(),
                    "The pressure gauge's value in the unblocked flow, Pa (e.g. from a run "
                    "without the bodies). Empty: the mean over the reference window.");
  prm.declare_entry("reference flow", "", Anything(),
                    "The flow gauge's value in the unblocked flow (m^2/s in 2D, m^3/s in 3D). "
                    "Empty: the mean over the reference window.");
  prm.declare_entry("reference window", "", Anything(),
                    "'t0, t1': the probe rows in [t0, t1] (s) whose mean is a reference that "
                    "is not given (the flow developed, no body there yet).");
  prm.declare_entry("start time", "0", Double(0),
                    "Probe rows before this time (the flow's start-up and its first pressure "
                    "waves) are not watched, s.");
  prm.declare_entry("stop after", "", Anything(),
                    "End the run (finished) this long after the jam, s: a study of the time to "
                    "jam needs no more, and a flow-fed channel that a jam has closed only "
                    "compresses further. Empty: run to the end time.");
  prm.declare_entry("averaging time", "0.002", Double(0),
                    "The running mean's length, s (several probe intervals; longer than the "
                    "flow's acoustic ringing).");
  prm.leave_subsection();
  prm.leave_subsection();
}

template <int dim>
JamWatchSettings read_jam_watch_keys(ParameterHandler& prm, const sph::CaseDescription<dim>& c)
{
  const std::string where = "probes/jam watch/";
  prm.enter_subsection("probes");
  prm.enter_subsection("jam watch");
  JamWatchSettings w;
  w.pressure_gauge = trim(prm.get("pressure gauge"));
  w.flow_gauge = trim(prm.get("flow gauge"));
  w.pressure_factor = prm.get_double("pressure factor");
  w.flow_fraction = prm.get_double("flow fraction");
  w.averaging_time = prm.get_double("averaging time");
  w.start_time = prm.get_double("start time");
  // An optional number: empty leaves `value` as it is.
  const auto optional = [&](const std::string& key, double& value, bool zero_allowed)
  {
    const auto v = numbers(where + key, prm.get(key));
    if (v.size() > 1 || (v.size() == 1 && !(v[0] > 0 || (zero_allowed && v[0] == 0))))
      throw InputError(where + key, "'" + prm.get(key) + "': one " +
                                        (zero_allowed ? "time >= 0" : "positive number") +
                                        " expected");
    if (v.size() == 1)
      value = v[0];
  };
  optional("reference pressure", w.reference_pressure, false);
  optional("reference flow", w.reference_flow, false);
  optional("stop after", w.stop_after, true);
  const auto window = numbers(where + "reference window", prm.get("reference window"));
  prm.leave_subsection();
  prm.leave_subsection();
  if (!w.enabled())
    return w;
  const bool needs_window = (!w.pressure_gauge.empty() && std::isnan(w.reference_pressure)) ||
                            (!w.flow_gauge.empty() && std::isnan(w.reference_flow));
  if (!window.empty() && (window.size() != 2 || !(window[1] > window[0]) || window[0] < 0))
    throw InputError(where + "reference window", "'t0, t1' with 0 <= t0 < t1 expected");
  if (needs_window && window.empty())
    throw InputError(where + "reference window",
                     "needed: a gauge without its `reference pressure` or `reference flow` takes "
                     "its reference as the mean over this window ('t0, t1', s)");
  if (!window.empty())
  {
    w.reference_start = window[0];
    w.reference_end = window[1];
  }
  if (!(w.averaging_time > 0))
    throw InputError(where + "averaging time", "must be positive");
  // The gauges must exist: a misspelt name would otherwise watch nothing.
  const auto known = [](const auto& gauges, const std::string& name)
  {
    for (const auto& g : gauges)
      if (g.name == name)
        return true;
    return false;
  };
  if (!w.pressure_gauge.empty() && !known(c.pressure_probes, w.pressure_gauge))
    throw InputError(where + "pressure gauge",
                     "'" + w.pressure_gauge + "' is not among probes/pressure");
  if (!w.flow_gauge.empty() && !known(c.flow_sections, w.flow_gauge))
    throw InputError(where + "flow gauge", "'" + w.flow_gauge + "' is not among probes/flow rate");
  return w;
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
template JamWatchSettings read_jam_watch_keys(ParameterHandler&, const sph::CaseDescription<2>&);
template JamWatchSettings read_jam_watch_keys(ParameterHandler&, const sph::CaseDescription<3>&);
} // namespace chipflex::apps
