#pragma once
// Force elements between two body frames (or a frame and the ground): they add to the
// generalised forces and to the Newton tangent. One class per element kind.

#include "mbs/joint.h"

#include <Eigen/Dense>

namespace chipflex::mbs
{
template <int dim>
class ForceElement
{
public:
  ForceElement(int body_a, int body_b) : body_a_(body_a), body_b_(body_b) {}
  virtual ~ForceElement() = default;
  int body_a() const { return body_a_; }
  int body_b() const { return body_b_; }
  /// Adds the element's generalised forces to f (all system velocities).
  virtual void add_forces(const BodyView<dim>& a, const BodyView<dim>& b,
                          Eigen::Ref<Eigen::VectorXd> f) const = 0;
  /// Adds c_k K + c_d D (K = -df/dq, D = -df/dv) to the Newton matrix s.
  virtual void add_tangent(const BodyView<dim>& a, const BodyView<dim>& b, double c_k, double c_d,
                           Eigen::Ref<Eigen::MatrixXd> s) const = 0;

private:
  int body_a_, body_b_;
};

/// Linear torsion spring and damper across a planar revolute joint: moment
/// -(c phi + d phi') on b and the opposite on a, phi = theta_b - theta_a - rest_angle.
/// 2D only (per metre of depth: c in Nm/rad per metre). Exact tangent.
class TorsionSpring : public ForceElement<2>
{
public:
  TorsionSpring(int body_a, int body_b, double stiffness, double damping = 0,
                double rest_angle = 0);
  void add_forces(const BodyView<2>& a, const BodyView<2>& b,
                  Eigen::Ref<Eigen::VectorXd> f) const override;
  void add_tangent(const BodyView<2>& a, const BodyView<2>& b, double c_k, double c_d,
                   Eigen::Ref<Eigen::MatrixXd> s) const override;
  double stiffness() const { return stiffness_; }
  /// phi = theta_b - theta_a - rest angle in the current state.
  double deflection(const BodyView<2>& a, const BodyView<2>& b) const;

private:
  double stiffness_, damping_, rest_angle_;
};
} // namespace chipflex::mbs
