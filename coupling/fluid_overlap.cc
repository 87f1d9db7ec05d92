#include "coupling/fluid_overlap.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>

namespace chipflex::coupling
{
namespace
{
constexpr double pi = 3.14159265358979323846;

/// Distance from x to the segment or triangle.
double face_distance(const Eigen::Vector2d& x, const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  const Eigen::Vector2d e = b - a;
  const double t = std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return (a + t * e - x).norm();
}

double face_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                     const Eigen::Vector3d& c)
{
  // Foot point inside the triangle: the plane distance; otherwise the nearest edge.
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double area2 = n.squaredNorm();
  if (area2 > 0)
  {
    const Eigen::Vector3d p = x - n * (x - a).dot(n) / area2;
    const double u = (b - p).cross(c - p).dot(n), v = (c - p).cross(a - p).dot(n),
                 w = (a - p).cross(b - p).dot(n);
    if (u >= 0 && v >= 0 && w >= 0)
      return std::abs((x - a).dot(n)) / std::sqrt(area2);
  }
  auto edge = [&](const Eigen::Vector3d& p, const Eigen::Vector3d& q)
  {
    const Eigen::Vector3d e = q - p;
    const double t =
        e.squaredNorm() > 0 ? std::clamp((x - p).dot(e) / e.squaredNorm(), 0.0, 1.0) : 0;
    return (p + t * e - x).norm();
  };
  return std::min({edge(a, b), edge(b, c), edge(c, a)});
}
} // namespace

template <int dim>
SkinOverlap<dim>::SkinOverlap(std::vector<Vector> nodes, std::vector<std::array<int, dim>> faces,
                              double margin)
    : nodes_(std::move(nodes)), faces_(std::move(faces)), margin_(margin)
{
  // Closed: every edge (3D) or node (2D) shared by exactly two faces.
  std::map<std::array<int, 2>, int> count;
  for (const auto& f : faces_)
    for (int k = 0; k < dim; ++k)
    {
      std::array<int, 2> e =
          dim == 2 ? std::array<int, 2>{f[k], f[k]} : std::array<int, 2>{f[k], f[(k + 1) % dim]};
      if (e[0] > e[1])
        std::swap(e[0], e[1]);
      ++count[e];
    }
  closed_ = !faces_.empty();
  for (const auto& [e, n] : count)
    closed_ = closed_ && n == 2;
  lower_ = upper_ = nodes_.empty() ? Vector::Zero() : nodes_.front();
  for (const auto& x : nodes_)
  {
    lower_ = lower_.cwiseMin(x);
    upper_ = upper_.cwiseMax(x);
  }
  lower_.array() -= margin_;
  upper_.array() += margin_;
}

template <int dim>
bool SkinOverlap<dim>::operator()(const Vector& x) const
{
  return near_face(x) || encloses(x);
}

template <int dim>
bool SkinOverlap<dim>::near_face(const Vector& x) const
{
  if ((x.array() < lower_.array()).any() || (x.array() > upper_.array()).any())
    return false;
  for (const auto& f : faces_)
  {
    if constexpr (dim == 2)
    {
      if (face_distance(x, nodes_[f[0]], nodes_[f[1]]) < margin_)
        return true;
    }
    else if (face_distance(x, nodes_[f[0]], nodes_[f[1]], nodes_[f[2]]) < margin_)
      return true;
  }
  return false;
}

template <int dim>
bool SkinOverlap<dim>::encloses(const Vector& x) const
{
  if (!closed_ || (x.array() < lower_.array()).any() || (x.array() > upper_.array()).any())
    return false;
  double winding = 0;
  for (const auto& f : faces_)
  {
    if constexpr (dim == 2)
    {
      const Vector a = nodes_[f[0]] - x, b = nodes_[f[1]] - x;
      winding += std::atan2(a[0] * b[1] - a[1] * b[0], a.dot(b)) / (2 * pi);
    }
    else
    {
      // Solid angle of the triangle (Van Oosterom & Strackee 1983).
      const Vector a = nodes_[f[0]] - x, b = nodes_[f[1]] - x, c = nodes_[f[2]] - x;
      const double la = a.norm(), lb = b.norm(), lc = c.norm();
      winding += 2 *
                 std::atan2(a.dot(b.cross(c)),
                            la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la) /
                 (4 * pi);
    }
  }
  return winding > 0.5;
}

template class SkinOverlap<2>;
template class SkinOverlap<3>;
} // namespace chipflex::coupling
