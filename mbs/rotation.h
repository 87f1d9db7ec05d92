#pragma once
// Small rotation helpers shared by the body and joint code. A frame's orientation is an
// angle theta in 2D and a unit quaternion in 3D; its angular velocity omega is expressed
// in the body frame (1 component in 2D, 3 in 3D). Increments of the orientation are
// rotation vectors in the body frame, applied on the right: A <- A exp(~dtheta), the
// Lie-group update of Bruels, Cardona & Arnold (2012).

#include <Eigen/Dense>

namespace chipflex::mbs
{
/// Number of rotational degrees of freedom of a frame: 1 in 2D, 3 in 3D.
template <int dim>
constexpr int rotation_dofs = dim == 2 ? 1 : 3;

/// The axial part of a mass-weighted outer product C(a, b) = sum_ij Ms_ij a_i b_j^T:
/// sum_ij Ms_ij a_i x b_j = eps : C(a, b). 2D: the scalar C01 - C10; 3D: the vector
/// (C12 - C21, C20 - C02, C01 - C10).
inline double axial(const Eigen::Matrix2d& c)
{
  return c(0, 1) - c(1, 0);
}
inline Eigen::Vector3d axial(const Eigen::Matrix3d& c)
{
  return {c(1, 2) - c(2, 1), c(2, 0) - c(0, 2), c(0, 1) - c(1, 0)};
}

/// Skew matrix: skew(a) b = a x b.
inline Eigen::Matrix3d skew(const Eigen::Vector3d& a)
{
  Eigen::Matrix3d s;
  s << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return s;
}

/// The 2D perpendicular: perp(a) = (-a_y, a_x) = e_z x a.
inline Eigen::Vector2d perp(const Eigen::Vector2d& a)
{
  return {-a.y(), a.x()};
}

/// 2D cross product (a scalar) and its 3D counterpart, so code can be written once.
inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  return a.x() * b.y() - a.y() * b.x();
}
inline Eigen::Vector3d cross(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return a.cross(b);
}

inline Eigen::Matrix2d rotation_matrix(double theta)
{
  const double c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix2d a;
  a << c, -s, s, c;
  return a;
}

/// exp of a rotation vector as a unit quaternion (exact for any angle).
inline Eigen::Quaterniond quaternion_exp(const Eigen::Vector3d& phi)
{
  const double angle = phi.norm();
  if (angle < 1e-8)
  {
    // Taylor series: sin(a/2)/a = 1/2 - a^2/48, exact to round-off below 1e-8.
    const Eigen::Vector3d v = phi * (0.5 - angle * angle / 48.0);
    return Eigen::Quaterniond(1.0 - angle * angle / 8.0, v.x(), v.y(), v.z()).normalized();
  }
  const Eigen::Vector3d v = phi * (std::sin(0.5 * angle) / angle);
  return Eigen::Quaterniond(std::cos(0.5 * angle), v.x(), v.y(), v.z());
}
} // namespace chipflex::mbs
