#pragma once
// A wall with a prescribed rigid motion, as a coupled body: its skin translates at a
// constant velocity and turns about an axis at a constant angular speed, whatever the
// fluid (or contact) does to it. A turning drill moves the borehole wall past the flute
// this way, and a piston or a sliding lid too. It reports the force and the torque about
// its axis that it receives, which is what its drive has to supply.
//
//   x(t) = c(t) + R(omega t) (x0 - c0),   c(t) = c0 + v t,   x'(t) = v + omega a x (x - c(t))
//
// 2D: the axis is z, the angular speed counter-clockwise positive. With `in_place` the
// vertices stay at x0 (the motion only sets their velocities, x'(t) = v + omega a x
// (x0 - c(t))): exact for a surface the motion maps onto itself.

#include "coupling/coupled_body.h"
#include "mbs/skin_body.h"

#include <Eigen/Geometry>
#include <limits>

namespace chipflex::coupling
{
template <int dim>
struct PrescribedMotion
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  Vector velocity = Vector::Zero();                ///< translation, m/s
  Vector centre = Vector::Zero();                  ///< a point of the axis at t = 0, m
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ(); ///< rotation axis (3D), unit
  double angular_speed = 0;                        ///< rad/s, right-handed about the axis
  /// The surface keeps its place and only its velocity follows the motion: a surface
  /// that moves along itself (a turning surface of revolution about its axis, a belt),
  /// given only where the fluid or the bodies meet it (a borehole wall beside a flute).
  bool in_place = false;
};

template <int dim>
class PrescribedMotionBody : public CoupledBody<dim>, public mbs::SkinBody<dim>
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  using Matrix = Eigen::Matrix<double, dim, dim>;

  /// `nodes` and `faces`: the wall at t = 0 (world, fluid on the side of the face normal).
  PrescribedMotionBody(std::vector<Vector> nodes, std::vector<std::array<int, dim>> faces,
                       const PrescribedMotion<dim>& motion);

  // CoupledBody
  std::string kind() const override { return "moving-wall"; }
  mbs::SkinBody<dim>& skin() override { return *this; }
  void advance(double dt) override;
  /// Infinite: nothing moves it off its path (contact treats it as a moving obstacle).
  double mass() const override { return std::numeric_limits<double>::infinity(); }
  /// The impulse it has taken (its drive holds it on its path whatever the load).
  Vector linear_momentum() const override { return impulse_; }
  /// The point c(t) of the axis.
  Vector probe_position() const override;
  Matrix frame_rotation() const override;
  /// force_x_N, force_y_N(, force_z_N), torque_Nm (about the axis through c(t)).
  std::vector<std::pair<std::string, double>> extra_probes() const override;
  std::vector<double> state() const override;
  void restore(const std::vector<double>& state) override;

  // SkinBody
  std::size_t n_skin_nodes() const override { return reference_.size(); }
  const std::vector<std::array<int, dim>>& skin_faces() const override { return faces_; }
  void skin_positions(std::vector<Vector>& x) const override;
  void skin_velocities(std::vector<Vector>& v) const override;
  bool skin_slides_in_place() const override { return motion_.in_place; }
  void set_skin_forces(const std::vector<Vector>& f) override { forces_ = f; }

  double time() const { return time_; }

private:
  /// omega x r with the axis (2D: about z).
  Vector spin(const Vector& r) const;

  std::vector<Vector> reference_;
  std::vector<std::array<int, dim>> faces_;
  PrescribedMotion<dim> motion_;
  std::vector<Vector> forces_;
  double time_ = 0;
  Vector impulse_ = Vector::Zero();
};
} // namespace chipflex::coupling
