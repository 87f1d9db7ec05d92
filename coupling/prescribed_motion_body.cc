#include "coupling/prescribed_motion_body.h"

#include "common/input_error.h"

#include <cmath>

namespace chipflex::coupling
{
template <int dim>
PrescribedMotionBody<dim>::PrescribedMotionBody(std::vector<Vector> nodes,
                                                std::vector<std::array<int, dim>> faces,
                                                const PrescribedMotion<dim>& motion)
    : reference_(std::move(nodes)), faces_(std::move(faces)), motion_(motion),
      forces_(reference_.size(), Vector::Zero())
{
  if (!(motion_.axis.norm() > 0))
    throw InputError("moving wall, rotation axis", "must not be the zero vector");
  motion_.axis.normalize();
}

template <int dim>
typename PrescribedMotionBody<dim>::Vector PrescribedMotionBody<dim>::probe_position() const
{
  return motion_.in_place ? motion_.centre : motion_.centre + motion_.velocity * time_;
}

template <int dim>
typename PrescribedMotionBody<dim>::Matrix PrescribedMotionBody<dim>::frame_rotation() const
{
  const double angle = motion_.angular_speed * time_;
  if constexpr (dim == 2)
    return Eigen::Rotation2Dd(angle).toRotationMatrix();
  else
    return Eigen::AngleAxisd(angle, motion_.axis).toRotationMatrix();
}

template <int dim>
typename PrescribedMotionBody<dim>::Vector PrescribedMotionBody<dim>::spin(const Vector& r) const
{
  if constexpr (dim == 2)
    return motion_.angular_speed * Vector(-r[1], r[0]);
  else
    return motion_.angular_speed * motion_.axis.cross(r);
}

template <int dim>
void PrescribedMotionBody<dim>::skin_positions(std::vector<Vector>& x) const
{
  if (motion_.in_place)
  {
    x = reference_;
    return;
  }
  const Matrix r = frame_rotation();
  const Vector c = probe_position();
  x.resize(reference_.size());
  for (std::size_t i = 0; i < reference_.size(); ++i)
    x[i] = c + r * (reference_[i] - motion_.centre);
}

template <int dim>
void PrescribedMotionBody<dim>::skin_velocities(std::vector<Vector>& v) const
{
  std::vector<Vector> x;
  skin_positions(x);
  const Vector c = probe_position();
  v.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    v[i] = motion_.velocity + spin(x[i] - c);
}

template <int dim>
void PrescribedMotionBody<dim>::advance(double dt)
{
  for (const auto& f : forces_)
    impulse_ += dt * f;
  time_ += dt;
}

template <int dim>
std::vector<std::pair<std::string, double>> PrescribedMotionBody<dim>::extra_probes() const
{
  std::vector<Vector> x;
  skin_positions(x);
  const Vector c = probe_position();
  Vector force = Vector::Zero();
  double torque = 0;
  for (std::size_t i = 0; i < x.size() && i < forces_.size(); ++i)
  {
    force += forces_[i];
    const Vector r = x[i] - c;
    if constexpr (dim == 2)
      torque += r[0] * forces_[i][1] - r[1] * forces_[i][0];
    else
      torque += motion_.axis.dot(r.cross(forces_[i]));
  }
  const char* axis[3] = {"x", "y", "z"};
  std::vector<std::pair<std::string, double>> out;
  for (int d = 0; d < dim; ++d)
    out.emplace_back(std::string("force_") + axis[d] + "_N", force[d]);
  out.emplace_back("torque_Nm", torque);
  return out;
}

template <int dim>
std::vector<double> PrescribedMotionBody<dim>::state() const
{
  std::vector<double> s{time_};
  for (int d = 0; d < dim; ++d)
    s.push_back(impulse_[d]);
  return s;
}

template <int dim>
void PrescribedMotionBody<dim>::restore(const std::vector<double>& s)
{
  if (s.size() != 1 + dim)
    throw InputError("moving wall state", "expected " + std::to_string(1 + dim) + " numbers");
  time_ = s[0];
  for (int d = 0; d < dim; ++d)
    impulse_[d] = s[1 + d];
}

template class PrescribedMotionBody<2>;
template class PrescribedMotionBody<3>;
} // namespace chipflex::coupling
