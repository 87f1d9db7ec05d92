#pragma once
// Geometry of one wall face (segment in 2D, triangle in 3D): unit normal on the fluid
// side, and the projection of a point: signed distance along the normal and the
// barycentric weights of the foot point. The same weights place a contact and
// distribute its reaction on the vertices, which is what makes the wall momentum
// conserving (the weights sum to one).

#include "sph/wall_surface.h"

#include <Eigen/Geometry>
#include <array>
#include <cmath>

namespace chipflex::sph
{
template <int dim>
struct FaceProjection
{
  Eigen::Matrix<double, dim, 1> normal; ///< unit, fluid side
  double distance;                      ///< signed, positive on the fluid side
  std::array<double, dim> weights;      ///< barycentric, unclamped (sum 1)
  bool inside;                          ///< foot point within the face (weights >= 0)
};

template <int dim>
FaceProjection<dim> project_on_face(const WallSurface<dim>& wall, int face,
                                    const Eigen::Matrix<double, dim, 1>& x)
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  FaceProjection<dim> p;
  const auto& f = wall.faces[face];
  const Vector& a = wall.vertices[f[0]];
  if constexpr (dim == 2)
  {
    const Vector e = wall.vertices[f[1]] - a;
    const double l2 = e.squaredNorm();
    p.normal = Vector(e[1], -e[0]) / std::sqrt(l2);
    const double t = (x - a).dot(e) / l2;
    p.weights = {1 - t, t};
    p.distance = (x - a).dot(p.normal);
    p.inside = t >= 0 && t <= 1;
  }
  else
  {
    const Vector e1 = wall.vertices[f[1]] - a, e2 = wall.vertices[f[2]] - a;
    const Vector n = e1.cross(e2);
    p.normal = n.normalized();
    const Vector w = x - a;
    // Barycentric coordinates of the foot point (Ericson, Real-Time Collision Detection).
    const double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2);
    const double w1 = w.dot(e1), w2 = w.dot(e2);
    const double den = d11 * d22 - d12 * d12;
    const double u = (d22 * w1 - d12 * w2) / den, v = (d11 * w2 - d12 * w1) / den;
    p.weights = {1 - u - v, u, v};
    p.distance = w.dot(p.normal);
    p.inside = u >= 0 && v >= 0 && u + v <= 1;
  }
  return p;
}

/// The point with barycentric `weights` on the face, moved `offset` along its normal.
template <int dim>
Eigen::Matrix<double, dim, 1> point_on_face(const WallSurface<dim>& wall, int face,
                                            const std::array<double, std::size_t(dim)>& weights,
                                            double offset)
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  const auto& f = wall.faces[face];
  Vector x = Vector::Zero();
  for (int k = 0; k < dim; ++k)
    x += weights[k] * wall.vertices[f[k]];
  Vector n;
  if constexpr (dim == 2)
  {
    const Vector e = wall.vertices[f[1]] - wall.vertices[f[0]];
    n = Vector(e[1], -e[0]).normalized();
  }
  else
    n = (wall.vertices[f[1]] - wall.vertices[f[0]])
            .cross(wall.vertices[f[2]] - wall.vertices[f[0]])
            .normalized();
  return x + offset * n;
}
} // namespace chipflex::sph
