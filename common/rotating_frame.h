#pragma once
// A reference frame that turns about a fixed axis: the drill's frame, in which the drill's
// flute stands still and the borehole wall turns past it. Newton's law written in such a
// frame carries three fictitious accelerations (e.g. Goldstein, Poole & Safko, Classical
// Mechanics, 3rd ed., sec. 4.10):
//
//     a_fict = - Omega x (Omega x r) - 2 Omega x v - dOmega/dt x r,   r = x - axis point,
//
// centrifugal, Coriolis and Euler (the last only while the speed changes). Omega grows
// smoothly from 0 over the spin-up time and then stays: a case can start at rest and reach
// the drill's speed without a jolt. In 2D the frame turns about the out-of-plane axis z.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace chipflex
{
struct RotatingFrame
{
  /// The frame's angular velocity once spun up, rad/s, world axes (2D: only z).
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  /// A point on the axis of rotation, m.
  Eigen::Vector3d axis_point = Eigen::Vector3d::Zero();
  /// Omega ramps from 0 at t = 0 to angular_velocity at this time, s (0: at once).
  double spin_up_time = 0;

  bool active() const { return angular_velocity.squaredNorm() > 0; }

  /// Fraction of the final speed reached at time t: (1 - cos(pi t / T)) / 2 during the
  /// spin-up, so that dOmega/dt starts and ends at 0 (no jolt; a kink in Omega would
  /// cost a time integrator its second order).
  double ramp(double t) const
  {
    if (!(spin_up_time > 0) || t >= spin_up_time)
      return 1;
    return t <= 0 ? 0 : 0.5 * (1 - std::cos(M_PI * t / spin_up_time));
  }
  Eigen::Vector3d omega(double t) const { return ramp(t) * angular_velocity; }
  /// dOmega/dt at time t.
  Eigen::Vector3d alpha(double t) const
  {
    if (!(spin_up_time > 0) || t <= 0 || t >= spin_up_time)
      return Eigen::Vector3d::Zero();
    return 0.5 * M_PI / spin_up_time * std::sin(M_PI * t / spin_up_time) * angular_velocity;
  }
  /// Angle the frame has turned through from t = 0 to t, rad.
  double angle(double t) const
  {
    const double w = angular_velocity.norm();
    if (!(spin_up_time > 0))
      return w * std::max(t, 0.0);
    const double tr = std::clamp(t, 0.0, spin_up_time);
    return w * (0.5 * tr - 0.5 * spin_up_time / M_PI * std::sin(M_PI * tr / spin_up_time)) +
           w * std::max(t - spin_up_time, 0.0);
  }

  /// The frame's motion at one instant, for evaluating many points.
  struct Instant
  {
    Eigen::Vector3d omega, alpha, axis_point;
    /// The fictitious acceleration of a point at x moving with v (both in the frame).
    template <int dim>
    Eigen::Matrix<double, dim, 1> acceleration(const Eigen::Matrix<double, dim, 1>& x,
                                               const Eigen::Matrix<double, dim, 1>& v) const
    {
      Eigen::Vector3d r = Eigen::Vector3d::Zero(), u = Eigen::Vector3d::Zero();
      r.head<dim>() = x - axis_point.head<dim>();
      u.head<dim>() = v;
      const Eigen::Vector3d a = -omega.cross(omega.cross(r)) - 2 * omega.cross(u) - alpha.cross(r);
      return a.head<dim>();
    }
  };
  Instant at(double t) const { return {omega(t), alpha(t), axis_point}; }

  template <int dim>
  Eigen::Matrix<double, dim, 1> acceleration(double t, const Eigen::Matrix<double, dim, 1>& x,
                                             const Eigen::Matrix<double, dim, 1>& v) const
  {
    return at(t).template acceleration<dim>(x, v);
  }
};
} // namespace chipflex
