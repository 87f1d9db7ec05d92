#include "mbs/joint.h"

namespace chipflex::mbs
{
namespace
{
template <int dim>
Eigen::Matrix<double, dim, dim> frame_rotation(const BodyView<dim>& v)
{
  return v.body ? v.body->rotation() : Eigen::Matrix<double, dim, dim>::Identity();
}

/// The row d(n_a . e_b)/dv of a dot constraint between world unit vectors n (on a) and
/// e (on b): d(n.e) = (dphi_a - dphi_b) . (n x e), with dphi = A dtheta (world).
void dot_constraint_row(const BodyView<3>& a, const BodyView<3>& b, const Eigen::Vector3d& n,
                        const Eigen::Vector3d& e, Eigen::Ref<Eigen::MatrixXd> jacobian, int row)
{
  const Eigen::Vector3d c = n.cross(e);
  if (a.body && a.body->rotation_offset() >= 0)
    jacobian.block<1, 3>(row, a.offset + 3) += c.transpose() * a.body->rotation();
  if (b.body && b.body->rotation_offset() >= 0)
    jacobian.block<1, 3>(row, b.offset + 3) -= c.transpose() * b.body->rotation();
}
} // namespace

template <int dim>
void Joint<dim>::coincident_points(const BodyView<dim>& a, const Vector& p_a,
                                   const BodyView<dim>& b, const Vector& p_b, int row,
                                   Eigen::Ref<Eigen::VectorXd> g,
                                   Eigen::Ref<Eigen::MatrixXd> jacobian) const
{
  const Vector xa = a.body ? a.body->point_position(p_a) : p_a;
  const Vector xb = b.body ? b.body->point_position(p_b) : p_b;
  g.template segment<dim>(row) = xa - xb;
  typename FloatingFrameBody<dim>::PointJacobian j;
  if (a.body)
  {
    j.resize(dim, a.body->n_velocities());
    a.body->point_jacobian(p_a, j);
    jacobian.block(row, a.offset, dim, j.cols()) += j;
  }
  if (b.body)
  {
    j.resize(dim, b.body->n_velocities());
    b.body->point_jacobian(p_b, j);
    jacobian.block(row, b.offset, dim, j.cols()) -= j;
  }
}

template <int dim>
RevoluteJoint<dim>::RevoluteJoint(int body_a, const Vector& point_a, int body_b,
                                  const Vector& point_b, const Eigen::Vector3d& axis_a,
                                  const Eigen::Vector3d& axis_b)
    : Joint<dim>(body_a, body_b), point_a_(point_a), point_b_(point_b), axis_a_(axis_a.normalized())
{
  // two unit vectors normal to axis_b: n_a . e_b1 = n_a . e_b2 = 0 keeps the axes parallel
  const Eigen::Vector3d nb = axis_b.normalized();
  const Eigen::Vector3d trial =
      std::abs(nb.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  normal_b1_ = nb.cross(trial).normalized();
  normal_b2_ = nb.cross(normal_b1_);
}

template <int dim>
void RevoluteJoint<dim>::evaluate(const BodyView<dim>& a, const BodyView<dim>& b,
                                  Eigen::Ref<Eigen::VectorXd> g,
                                  Eigen::Ref<Eigen::MatrixXd> jacobian) const
{
  this->coincident_points(a, point_a_, b, point_b_, 0, g, jacobian);
  if constexpr (dim == 3)
  {
    const Eigen::Vector3d n = frame_rotation(a) * axis_a_;
    const Eigen::Vector3d e1 = frame_rotation(b) * normal_b1_;
    const Eigen::Vector3d e2 = frame_rotation(b) * normal_b2_;
    g(3) = n.dot(e1);
    g(4) = n.dot(e2);
    dot_constraint_row(a, b, n, e1, jacobian, 3);
    dot_constraint_row(a, b, n, e2, jacobian, 4);
  }
}

template <int dim>
FixedJoint<dim>::FixedJoint(int body_a, const Vector& point_a, int body_b, const Vector& point_b,
                            const Eigen::Matrix3d& relative_rotation)
    : Joint<dim>(body_a, body_b), point_a_(point_a), point_b_(point_b),
      relative_rotation_(relative_rotation)
{
}

template <int dim>
void FixedJoint<dim>::evaluate(const BodyView<dim>& a, const BodyView<dim>& b,
                               Eigen::Ref<Eigen::VectorXd> g,
                               Eigen::Ref<Eigen::MatrixXd> jacobian) const
{
  this->coincident_points(a, point_a_, b, point_b_, 0, g, jacobian);
  if constexpr (dim == 2)
  {
    // theta_b - theta_a - relative angle (unwrapped angles, so no branch cut)
    const double rel = std::atan2(relative_rotation_(1, 0), relative_rotation_(0, 0));
    const double ta = a.body ? a.body->angle() : 0.0;
    const double tb = b.body ? b.body->angle() : 0.0;
    g(2) = tb - ta - rel;
    if (a.body && a.body->rotation_offset() >= 0)
      jacobian(2, a.offset + 2) -= 1;
    if (b.body && b.body->rotation_offset() >= 0)
      jacobian(2, b.offset + 2) += 1;
  }
  else
  {
    // Triads a_i = A_a R_rel e_i and b_i = A_b e_i coincide when a_y.b_z = a_z.b_x =
    // a_x.b_y = 0 near the assembled pose (small rotations about x, y, z respectively).
    const Eigen::Matrix3d ta = frame_rotation(a) * relative_rotation_;
    const Eigen::Matrix3d tb = frame_rotation(b);
    const int pairs[3][2] = {{1, 2}, {2, 0}, {0, 1}};
    for (int r = 0; r < 3; ++r)
    {
      const Eigen::Vector3d n = ta.col(pairs[r][0]), e = tb.col(pairs[r][1]);
      g(3 + r) = n.dot(e);
      dot_constraint_row(a, b, n, e, jacobian, 3 + r);
    }
  }
}

template class Joint<2>;
template class Joint<3>;
template class RevoluteJoint<2>;
template class RevoluteJoint<3>;
template class FixedJoint<2>;
template class FixedJoint<3>;
} // namespace chipflex::mbs
