#include "apps/chip_source_case_keys.h"

#include "apps/case_values.h"
#include "common/input_error.h"

#include <Eigen/Geometry>
#include <cmath>
#include <deal.II/base/parameter_handler.h>

namespace chipflex::apps
{
using dealii::ParameterHandler;
using dealii::Patterns::Anything;
using dealii::Patterns::Double;

void declare_chip_source_keys(ParameterHandler& prm)
{
  prm.enter_subsection("chip source");
  prm.declare_entry("bodies", "", Anything(),
                    "The chip source's pool: names of rigid or flexible bodies of this case, "
                    "parked where the case places them (away from the fluid) until released; "
                    "a chip that leaves through the exit plane is parked again and released "
                    "anew as a later chip. Empty: no chip source.");
  prm.declare_entry("first release", "0", Double(0), "Time of the first release, s.");
  prm.declare_entry("interval", "0", Double(0), "Time between releases, s (or revolutions).");
  prm.declare_entry("revolutions", "0", Double(0),
                    "Releases every this many revolutions of the rotating frame (a chip per "
                    "revolution of the drill: 1), instead of interval.");
  prm.declare_entry("position", "", Anything(),
                    "Where a released chip's body frame is put (the cutting edge), m.");
  prm.declare_entry("rotation axis", "0, 0, 1", Anything(),
                    "Its orientation: rotation about this axis (3D) by angle, from the body "
                    "file's.");
  prm.declare_entry("angle", "0", Double(), "Its orientation: the rotation angle, rad.");
  prm.declare_entry("velocity", "", Anything(),
                    "The released chip's velocity, m/s (the chip-flow speed: the cutting "
                    "speed over the chip compression ratio); empty: at rest.");
  prm.declare_entry("angular velocity", "0, 0, 0", Anything(),
                    "The released chip's angular velocity, rad/s (world axes; 2D: z).");
  prm.declare_entry("exit point", "", Anything(),
                    "A point on the exit plane, m: a chip whose skin's centre passes it "
                    "(along the exit normal) has left and is removed and counted.");
  prm.declare_entry("exit normal", "", Anything(), "The exit plane's normal, pointing out.");
  prm.leave_subsection();
}

template <int dim>
ChipSourceCase<dim> read_chip_source_keys(ParameterHandler& prm, const std::string& where,
                                          const RotatingFrame& frame)
{
  ChipSourceCase<dim> c;
  prm.enter_subsection("chip source");
  for (const std::string& name : split(prm.get("bodies"), ','))
    if (!trim(name).empty())
      c.bodies.push_back(trim(name));
  if (c.bodies.empty())
  {
    prm.leave_subsection();
    return c;
  }
  c.first_release = prm.get_double("first release");
  const double interval = prm.get_double("interval"), revolutions = prm.get_double("revolutions");
  if ((interval > 0) == (revolutions > 0))
    throw InputError(where + ", interval", "give exactly one of interval and revolutions");
  if (revolutions > 0)
  {
    if (!frame.active())
      throw InputError(where + ", revolutions", "needs a rotating frame (its angular velocity)");
    c.interval = revolutions * 2 * M_PI / frame.angular_velocity.norm();
  }
  else
    c.interval = interval;
  auto required = [&](const std::string& key)
  {
    if (trim(prm.get(key)).empty())
      throw InputError(where + ", " + key, "must be given for a chip source");
    return vector_of<dim>(where + ", " + key, prm.get(key));
  };
  c.position = required("position");
  c.exit_point = required("exit point");
  c.exit_normal = required("exit normal");
  if (!(c.exit_normal.norm() > 0))
    throw InputError(where + ", exit normal", "must not be the zero vector");
  if (!trim(prm.get("velocity")).empty())
    c.velocity = vector_of<dim>(where + ", velocity", prm.get("velocity"));
  c.angular_velocity = vector_of<3>(where + ", angular velocity", prm.get("angular velocity"));
  if (dim == 2 && c.angular_velocity.template head<2>().norm() > 0)
    throw InputError(where + ", angular velocity", "a 2D chip turns about z only: 0, 0, w");
  const double angle = prm.get_double("angle");
  if constexpr (dim == 2)
    c.rotation = Eigen::Rotation2Dd(angle).toRotationMatrix();
  else
  {
    const Eigen::Vector3d axis = vector_of<3>(where + ", rotation axis", prm.get("rotation axis"));
    if (!(axis.norm() > 0))
      throw InputError(where + ", rotation axis", "must not be the zero vector");
    c.rotation = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  }
  prm.leave_subsection();
  return c;
}

template ChipSourceCase<2> read_chip_source_keys(ParameterHandler&, const std::string&,
                                                 const RotatingFrame&);
template ChipSourceCase<3> read_chip_source_keys(ParameterHandler&, const std::string&,
                                                 const RotatingFrame&);
} // namespace chipflex::apps
