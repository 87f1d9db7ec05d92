#include "apps/contact_case_keys.h"

#include "apps/case_values.h"
#include "common/input_error.h"

#include <deal.II/base/parameter_handler.h>
#include <sstream>

namespace chipflex::apps
{
using dealii::ParameterHandler;
using dealii::Patterns::Anything;
using dealii::Patterns::Bool;
using dealii::Patterns::Double;

namespace
{
std::string text(double value)
{
  std::ostringstream s;
  s << value;
  return s.str();
}
} // namespace

void declare_contact_keys(ParameterHandler& prm)
{
  const coupling::ContactParameters d;
  prm.enter_subsection("contact");
  prm.declare_entry("enabled", "false", Bool(),
                    "Bodies collide with the walls (tank, polylines, permeable barriers) and "
                    "with each other: penalty spring-dashpot plus Coulomb friction on the skin "
                    "nodes (docs/contact.md).");
  prm.declare_entry("restitution", text(d.restitution), Double(0, 1),
                    "Coefficient of restitution e (normal relative speed after / before), in "
                    "(0, 1]; sets the contact damping, zeta = -ln e / sqrt(pi^2 + ln^2 e), -.");
  prm.declare_entry("friction coefficient", text(d.friction), Double(0),
                    "Coulomb friction coefficient mu (static = kinetic), -.");
  prm.declare_entry("stiffness", "0", Double(0),
                    "Normal stiffness per contact node, N/m per metre of depth (3D: N/m); 0: "
                    "derived per pair, m_r / n (pi / (steps dt))^2 (m_r: reduced mass of the "
                    "pair, n: its larger skin-node count, dt: the first fluid step).");
  prm.declare_entry("steps per contact", text(d.steps), Double(4),
                    "For the derived stiffness: time steps a contact on every node lasts, -.");
  prm.declare_entry("tangential stiffness ratio", text(d.tangential_ratio), Double(0),
                    "Tangential (sticking) spring over normal stiffness, -.");
  prm.declare_entry("thickness", "0", Double(0),
                    "Deepest overlap counted as contact, m; 0: half the shortest mean skin-edge "
                    "length of the bodies.");
  prm.declare_entry("torque axis", "", Anything(),
                    "The axis for the walls' contact probes (contact_<wall>_torque_Nm): 3D a "
                    "point and a direction 'x, y, z, ax, ay, az', 2D a point 'x, y' (about z), "
                    "m; empty: through the origin along z.");
  prm.leave_subsection();
}

ContactCase read_contact_case(ParameterHandler& prm, const std::string& case_path)
try
{
  ContactCase c;
  prm.enter_subsection("contact");
  c.enabled = prm.get_bool("enabled");
  auto& p = c.parameters;
  p.restitution = prm.get_double("restitution");
  p.friction = prm.get_double("friction coefficient");
  p.stiffness = prm.get_double("stiffness");
  p.steps = prm.get_double("steps per contact");
  p.tangential_ratio = prm.get_double("tangential stiffness ratio");
  p.thickness = prm.get_double("thickness");
  c.torque_axis = numbers("contact/torque axis", prm.get("torque axis"));
  prm.leave_subsection();
  coupling::check(p, "contact");
  prm.enter_subsection("geometry");
  prm.enter_subsection("walls");
  const bool barrier = prm.get("fluid passes").find_first_not_of(" \t") != std::string::npos;
  std::istringstream surfaces(prm.get("surfaces"));
  bool surface_barrier = false;
  for (std::string word; surfaces >> word;)
    surface_barrier = surface_barrier || word == "barrier" || word == "barrier;";
  prm.leave_subsection();
  prm.leave_subsection();
  if (surface_barrier && !c.enabled)
    throw InputError("geometry/walls/surfaces",
                     "a permeable barrier is felt by bodies only: set `enabled = true` in "
                     "`subsection contact`");
  if (barrier && !c.enabled)
    throw InputError("geometry/walls/fluid passes",
                     "a permeable barrier is felt by bodies only: set `enabled = true` in "
                     "`subsection contact`");
  return c;
}
catch (const InputError& e)
{
  throw InputError(case_path, e.what());
}
} // namespace chipflex::apps
