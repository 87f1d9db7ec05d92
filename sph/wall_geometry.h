#pragma once
// Geometry of one wall face (segment in 2D, triangle in 3D): unit normal on the fluid
// side, and the projection of a point: signed distance along the normal and the
// barycentric weights of the foot point. The same weights place a contact and
// distribute its reaction on the vertices, which is what makes the wall momentum
// conserving (the weights sum to one).

#include "sph/wall_surface.h"

#include <Eigen/Geometry>
#include <algorithm>
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

template <int dim>
struct ClosestPoint
{
  /// Nearest point of the face (edges included).
  Eigen::Matrix<double, dim, 1> point = Eigen::Matrix<double, dim, 1>::Zero();
  std::array<double, dim> weights{}; ///< its barycentric weights (all >= 0)
  double distance2 = 0;              ///< squared distance from the point asked about
  bool inside = false;               ///< the nearest point is the foot point (interior)
};

/// The point of a face nearest to x: the foot point where it falls on the face, else
/// the nearest point of its edges (3D: Ericson, Real-Time Collision Detection, 5.1.5).
template <int dim>
ClosestPoint<dim> closest_point_on_face(const WallSurface<dim>& wall, int face,
                                        const Eigen::Matrix<double, dim, 1>& x)
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  ClosestPoint<dim> c;
  const auto& f = wall.faces[face];
  const Vector& a = wall.vertices[f[0]];
  if constexpr (dim == 2)
  {
    const Vector e = wall.vertices[f[1]] - a;
    const double t = (x - a).dot(e) / e.squaredNorm();
    const double s = std::clamp(t, 0.0, 1.0);
    c.weights = {1 - s, s};
    c.inside = t > 0 && t < 1;
  }
  else
  {
    const Vector& b = wall.vertices[f[1]];
    const Vector& cc = wall.vertices[f[2]];
    const Vector ab = b - a, ac = cc - a, ap = x - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    c.inside = false;
    if (d1 <= 0 && d2 <= 0)
      c.weights = {1, 0, 0};
    else
    {
      const Vector bp = x - b;
      const double d3 = ab.dot(bp), d4 = ac.dot(bp);
      const Vector cp = x - cc;
      const double d5 = ab.dot(cp), d6 = ac.dot(cp);
      const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
      if (d3 >= 0 && d4 <= d3)
        c.weights = {0, 1, 0};
      else if (d6 >= 0 && d5 <= d6)
        c.weights = {0, 0, 1};
      else if (vc <= 0 && d1 >= 0 && d3 <= 0)
      {
        const double v = d1 / (d1 - d3);
        c.weights = {1 - v, v, 0};
      }
      else if (vb <= 0 && d2 >= 0 && d6 <= 0)
      {
        const double w = d2 / (d2 - d6);
        c.weights = {1 - w, 0, w};
      }
      else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
      {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        c.weights = {0, 1 - w, w};
      }
      else
      {
        const double den = 1 / (va + vb + vc);
        const double v = vb * den, w = vc * den;
        c.weights = {1 - v - w, v, w};
        c.inside = true;
      }
    }
  }
  c.point = Vector::Zero();
  for (int k = 0; k < dim; ++k)
    c.point += c.weights[k] * wall.vertices[f[k]];
  c.distance2 = (x - c.point).squaredNorm();
  return c;
}

/// Unit normal of a face on its fluid side (see WallSurface::faces).
template <int dim>
Eigen::Matrix<double, dim, 1> face_normal(const WallSurface<dim>& wall, int face)
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  const auto& f = wall.faces[face];
  if constexpr (dim == 2)
  {
    const Vector e = wall.vertices[f[1]] - wall.vertices[f[0]];
    return Vector(e[1], -e[0]).normalized();
  }
  else
    return (wall.vertices[f[1]] - wall.vertices[f[0]])
        .cross(wall.vertices[f[2]] - wall.vertices[f[0]])
        .normalized();
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
  return x + offset * face_normal(wall, face);
}
} // namespace chipflex::sph
