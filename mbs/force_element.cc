#include "mbs/force_element.h"

#include "common/input_error.h"

namespace chipflex::mbs
{
namespace
{
/// Column of the rotation of a planar frame; -1 for ground or a ground-clamped body.
int angle_column(const BodyView<2>& v)
{
  return v.body && v.body->rotation_offset() >= 0 ? v.offset + 2 : -1;
}
double angle(const BodyView<2>& v)
{
  return v.body ? v.body->angle() : 0.0;
}
double angular_velocity(const BodyView<2>& v)
{
  return v.body ? v.body->angular_velocity()(0) : 0.0;
}
} // namespace

TorsionSpring::TorsionSpring(int body_a, int body_b, double stiffness, double damping,
                             double rest_angle)
    : ForceElement<2>(body_a, body_b), stiffness_(stiffness), damping_(damping),
      rest_angle_(rest_angle)
{
  if (stiffness < 0 || damping < 0)
    throw InputError("torsion spring", "stiffness and damping must not be negative");
}

double TorsionSpring::deflection(const BodyView<2>& a, const BodyView<2>& b) const
{
  return angle(b) - angle(a) - rest_angle_;
}

void TorsionSpring::add_forces(const BodyView<2>& a, const BodyView<2>& b,
                               Eigen::Ref<Eigen::VectorXd> f) const
{
  const double moment =
      stiffness_ * deflection(a, b) + damping_ * (angular_velocity(b) - angular_velocity(a));
  if (const int ca = angle_column(a); ca >= 0)
    f(ca) += moment;
  if (const int cb = angle_column(b); cb >= 0)
    f(cb) -= moment;
}

void TorsionSpring::add_tangent(const BodyView<2>& a, const BodyView<2>& b, double c_k, double c_d,
                                Eigen::Ref<Eigen::MatrixXd> s) const
{
  const double k = c_k * stiffness_ + c_d * damping_;
  const int ca = angle_column(a), cb = angle_column(b);
  if (ca >= 0)
    s(ca, ca) += k;
  if (cb >= 0)
    s(cb, cb) += k;
  if (ca >= 0 && cb >= 0)
  {
    s(ca, cb) -= k;
    s(cb, ca) -= k;
  }
}
} // namespace chipflex::mbs
