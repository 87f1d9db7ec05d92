#pragma once
// Kinematic joints between body frames (or a body and the ground), enforced by Lagrange
// multipliers in the index-3 form g(q) = 0 (MultibodySystem). A joint gives its
// equations and their Jacobian with respect to the system velocities v (translations in
// world axes, rotations as body-frame angular velocities), so dg = G v dt.
//
// Joints attach to the *frame* of a floating-frame body: for a body with clamp modes
// (frame = clamp), a FixedJoint attaches its clamp to another body. Bodies clamped to
// ground contribute no columns (they act as ground).

#include "mbs/floating_frame_body.h"

#include <Eigen/Dense>

namespace chipflex::mbs
{
/// A body as the constraint code sees it: nullptr = ground; offset = first column.
template <int dim>
struct BodyView
{
  const FloatingFrameBody<dim>* body = nullptr;
  int offset = 0;
};

template <int dim>
class Joint
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  static constexpr int ground = -1;

  Joint(int body_a, int body_b) : body_a_(body_a), body_b_(body_b) {}
  virtual ~Joint() = default;
  int body_a() const { return body_a_; }
  int body_b() const { return body_b_; }
  virtual int n_equations() const = 0;
  /// g (n_equations) and rows of d g / d v (all system columns; the caller zeroes them).
  virtual void evaluate(const BodyView<dim>& a, const BodyView<dim>& b,
                        Eigen::Ref<Eigen::VectorXd> g,
                        Eigen::Ref<Eigen::MatrixXd> jacobian) const = 0;

protected:
  /// Rows r..r+dim: x_a(p_a) - x_b(p_b) (points in frame coordinates; ground: world).
  void coincident_points(const BodyView<dim>& a, const Vector& p_a, const BodyView<dim>& b,
                         const Vector& p_b, int row, Eigen::Ref<Eigen::VectorXd> g,
                         Eigen::Ref<Eigen::MatrixXd> jacobian) const;

private:
  int body_a_, body_b_;
};

/// Revolute joint: coincident points; in 3D also the axes (unit vectors in frame
/// coordinates of a and b) stay aligned. 2D: 2 equations, 3D: 5.
template <int dim>
class RevoluteJoint : public Joint<dim>
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  RevoluteJoint(int body_a, const Vector& point_a, int body_b, const Vector& point_b,
                const Eigen::Vector3d& axis_a = Eigen::Vector3d::UnitZ(),
                const Eigen::Vector3d& axis_b = Eigen::Vector3d::UnitZ());
  int n_equations() const override { return dim == 2 ? 2 : 5; }
  void evaluate(const BodyView<dim>& a, const BodyView<dim>& b, Eigen::Ref<Eigen::VectorXd> g,
                Eigen::Ref<Eigen::MatrixXd> jacobian) const override;

private:
  Vector point_a_, point_b_;
  Eigen::Vector3d axis_a_, normal_b1_, normal_b2_;
};

/// Fixed joint: coincident points and a fixed relative orientation, A_b = A_a R_rel.
/// 2D: 3 equations (relative angle), 3D: 6.
template <int dim>
class FixedJoint : public Joint<dim>
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  FixedJoint(int body_a, const Vector& point_a, int body_b, const Vector& point_b,
             const Eigen::Matrix3d& relative_rotation = Eigen::Matrix3d::Identity());
  int n_equations() const override { return dim == 2 ? 3 : 6; }
  void evaluate(const BodyView<dim>& a, const BodyView<dim>& b, Eigen::Ref<Eigen::VectorXd> g,
                Eigen::Ref<Eigen::MatrixXd> jacobian) const override;

private:
  Vector point_a_, point_b_;
  Eigen::Matrix3d relative_rotation_;
};
} // namespace chipflex::mbs
