#include "coupling/rigid_shapes.h"

#include "common/input_error.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace chipflex::coupling
{
namespace
{
constexpr double pi = 3.14159265358979323846;

int divisions(double length, double spacing, int at_least = 1)
{
  return std::max(at_least, static_cast<int>(std::ceil(length / spacing - 1e-9)));
}

/// Orients every triangle of a shape that is star-shaped about the origin (the
/// primitives) so that its normal points away from the origin.
void orient_outwards(const std::vector<Eigen::Vector3d>& x, std::vector<std::array<int, 3>>& faces)
{
  for (auto& f : faces)
  {
    const Eigen::Vector3d n = (x[f[1]] - x[f[0]]).cross(x[f[2]] - x[f[0]]);
    if (n.dot(x[f[0]] + x[f[1]] + x[f[2]]) < 0)
      std::swap(f[1], f[2]);
  }
}

/// Quads (a, b, c, d) as two triangles.
void add_quad(std::vector<std::array<int, 3>>& faces, int a, int b, int c, int d)
{
  faces.push_back({a, b, c});
  faces.push_back({a, c, d});
}

std::vector<Eigen::Vector2d> circle(double radius, double spacing)
{
  const int n = divisions(2 * pi * radius, spacing, 16);
  std::vector<Eigen::Vector2d> x;
  for (int k = 0; k < n; ++k)
    x.emplace_back(radius * std::cos(2 * pi * k / n), radius * std::sin(2 * pi * k / n));
  return x;
}

std::vector<std::array<int, 2>> closed_outline(int n)
{
  std::vector<std::array<int, 2>> faces;
  for (int k = 0; k < n; ++k)
    faces.push_back({k, (k + 1) % n});
  return faces;
}

void require_positive(double value, const std::string& what)
{
  if (!(value > 0))
    throw InputError(what, "must be positive, got " + std::to_string(value));
}
} // namespace

template <>
RigidShape<2> box_shape<2>(const Eigen::Vector2d& size, double density, double spacing)
{
  require_positive(size.minCoeff(), "box size");
  require_positive(density, "density");
  require_positive(spacing, "skin spacing");
  RigidShape<2> s;
  const double w = size[0], h = size[1];
  s.volume = w * h;
  s.mass = density * s.volume;
  s.inertia(2, 2) = s.mass * (w * w + h * h) / 12;
  const Eigen::Vector2d corner[4] = {
      {-w / 2, -h / 2}, {w / 2, -h / 2}, {w / 2, h / 2}, {-w / 2, h / 2}};
  for (int side = 0; side < 4; ++side)
  {
    const int n = divisions(side % 2 == 0 ? w : h, spacing);
    for (int k = 0; k < n; ++k)
      s.nodes.push_back(corner[side] + (corner[(side + 1) % 4] - corner[side]) * double(k) / n);
  }
  s.faces = closed_outline(int(s.nodes.size()));
  return s;
}

template <>
RigidShape<3> box_shape<3>(const Eigen::Vector3d& size, double density, double spacing)
{
  require_positive(size.minCoeff(), "box size");
  require_positive(density, "density");
  require_positive(spacing, "skin spacing");
  RigidShape<3> s;
  s.volume = size.prod();
  s.mass = density * s.volume;
  for (int a = 0; a < 3; ++a)
  {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    s.inertia(a, a) = s.mass * (size[b] * size[b] + size[c] * size[c]) / 12;
  }
  // Lattice points on the surface, shared between the faces that meet at an edge.
  const Eigen::Vector3i n(divisions(size[0], spacing), divisions(size[1], spacing),
                          divisions(size[2], spacing));
  std::map<std::array<int, 3>, int> id;
  auto vertex = [&](std::array<int, 3> ijk)
  {
    const auto [it, inserted] = id.emplace(ijk, int(s.nodes.size()));
    if (inserted)
    {
      Eigen::Vector3d x;
      for (int d = 0; d < 3; ++d)
        x[d] = size[d] * (double(ijk[d]) / n[d] - 0.5);
      s.nodes.push_back(x);
    }
    return it->second;
  };
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side)
    {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      for (int p = 0; p < n[b]; ++p)
        for (int q = 0; q < n[c]; ++q)
        {
          auto at = [&](int pb, int qc)
          {
            std::array<int, 3> ijk{};
            ijk[a] = side * n[a], ijk[b] = pb, ijk[c] = qc;
            return vertex(ijk);
          };
          add_quad(s.faces, at(p, q), at(p + 1, q), at(p + 1, q + 1), at(p, q + 1));
        }
    }
  orient_outwards(s.nodes, s.faces);
  return s;
}

template <>
RigidShape<2> sphere_shape<2>(double radius, double density, double spacing)
{
  require_positive(radius, "radius");
  require_positive(density, "density");
  require_positive(spacing, "skin spacing");
  RigidShape<2> s;
  s.volume = pi * radius * radius;
  s.mass = density * s.volume;
  s.inertia(2, 2) = s.mass * radius * radius / 2;
  s.nodes = circle(radius, spacing);
  s.faces = closed_outline(int(s.nodes.size()));
  return s;
}

template <>
RigidShape<3> sphere_shape<3>(double radius, double density, double spacing)
{
  require_positive(radius, "radius");
  require_positive(density, "density");
  require_positive(spacing, "skin spacing");
  RigidShape<3> s;
  s.volume = 4 * pi * radius * radius * radius / 3;
  s.mass = density * s.volume;
  s.inertia.diagonal().setConstant(0.4 * s.mass * radius * radius);
  // Latitude-longitude grid with single nodes at the poles.
  const int n_lat = divisions(pi * radius, spacing, 6), n_lon = 2 * n_lat;
  s.nodes.emplace_back(0, 0, -radius);
  for (int i = 1; i < n_lat; ++i)
  {
    const double theta = pi * i / n_lat;
    for (int j = 0; j < n_lon; ++j)
    {
      const double phi = 2 * pi * j / n_lon;
      s.nodes.emplace_back(radius * std::sin(theta) * std::cos(phi),
                           radius * std::sin(theta) * std::sin(phi), -radius * std::cos(theta));
    }
  }
  s.nodes.emplace_back(0, 0, radius);
  const int top = int(s.nodes.size()) - 1;
  auto ring = [&](int i, int j) { return 1 + (i - 1) * n_lon + (j % n_lon); };
  for (int j = 0; j < n_lon; ++j)
  {
    s.faces.push_back({0, ring(1, j + 1), ring(1, j)});
    s.faces.push_back({top, ring(n_lat - 1, j), ring(n_lat - 1, j + 1)});
    for (int i = 1; i + 1 < n_lat; ++i)
      add_quad(s.faces, ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i + 1, j));
  }
  orient_outwards(s.nodes, s.faces);
  return s;
}

template <>
RigidShape<2> cylinder_shape<2>(double radius, double, double density, double spacing)
{
  return sphere_shape<2>(radius, density, spacing);
}

template <>
RigidShape<3> cylinder_shape<3>(double radius, double length, double density, double spacing)
{
  require_positive(radius, "radius");
  require_positive(length, "length");
  require_positive(density, "density");
  require_positive(spacing, "skin spacing");
  RigidShape<3> s;
  s.volume = pi * radius * radius * length;
  s.mass = density * s.volume;
  s.inertia(0, 0) = s.inertia(1, 1) = s.mass * (3 * radius * radius + length * length) / 12;
  s.inertia(2, 2) = s.mass * radius * radius / 2;
  const auto rim = circle(radius, spacing);
  const int n_theta = int(rim.size());
  const int n_z = divisions(length, spacing), n_r = divisions(radius, spacing);
  // Rings: the side from bottom to top, then the caps' inner rings; a centre per cap.
  auto add_ring = [&](double r, double z)
  {
    const int first = int(s.nodes.size());
    for (const auto& p : rim)
      s.nodes.emplace_back(p[0] * r / radius, p[1] * r / radius, z);
    return first;
  };
  std::vector<int> side;
  for (int k = 0; k <= n_z; ++k)
    side.push_back(add_ring(radius, length * (double(k) / n_z - 0.5)));
  auto band = [&](int inner, int outer)
  {
    for (int j = 0; j < n_theta; ++j)
      add_quad(s.faces, inner + j, inner + (j + 1) % n_theta, outer + (j + 1) % n_theta, outer + j);
  };
  for (int k = 0; k < n_z; ++k)
    band(side[k], side[k + 1]);
  for (const double z : {-length / 2, length / 2})
  {
    int outer = z < 0 ? side.front() : side.back();
    for (int i = n_r - 1; i >= 1; --i)
    {
      const int inner = add_ring(radius * i / n_r, z);
      band(inner, outer);
      outer = inner;
    }
    const int centre = int(s.nodes.size());
    s.nodes.emplace_back(0, 0, z);
    for (int j = 0; j < n_theta; ++j)
      s.faces.push_back({centre, outer + j, outer + (j + 1) % n_theta});
  }
  orient_outwards(s.nodes, s.faces);
  return s;
}

template <>
RigidShape<2> closed_surface_shape<2>(const std::vector<Eigen::Vector2d>& nodes,
                                      std::vector<std::array<int, 2>> faces, double density,
                                      const std::string& where)
{
  require_positive(density, where + ": density");
  // A closed outline: every node starts one segment and ends one.
  std::vector<int> starts(nodes.size()), ends(nodes.size());
  for (const auto& f : faces)
  {
    if (f[0] < 0 || f[1] < 0 || f[0] >= int(nodes.size()) || f[1] >= int(nodes.size()))
      throw InputError(where, "a segment refers to a node that does not exist");
    ++starts[f[0]], ++ends[f[1]];
  }
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (starts[i] != ends[i] || starts[i] > 1)
      throw InputError(where, "the outline is not closed (node " + std::to_string(i) + " begins " +
                                  std::to_string(starts[i]) + " and ends " +
                                  std::to_string(ends[i]) + " segments)");
  // Green's theorem over the triangles (0, a, b).
  double area = 0, polar = 0;
  Eigen::Vector2d first = Eigen::Vector2d::Zero();
  for (const auto& f : faces)
  {
    const Eigen::Vector2d &a = nodes[f[0]], &b = nodes[f[1]];
    const double t = 0.5 * (a[0] * b[1] - a[1] * b[0]);
    area += t;
    first += t * (a + b) / 3;
    polar += t * (a.squaredNorm() + a.dot(b) + b.squaredNorm()) / 6;
  }
  if (area < 0)
  {
    for (auto& f : faces)
      std::swap(f[0], f[1]);
    area = -area, first = -first, polar = -polar;
  }
  if (!(area > 0))
    throw InputError(where, "the outline encloses no area");
  RigidShape<2> s;
  s.volume = area;
  s.mass = density * area;
  s.centre_of_mass = first / area;
  s.inertia(2, 2) = density * polar - s.mass * s.centre_of_mass.squaredNorm();
  s.nodes = nodes;
  s.faces = std::move(faces);
  return s;
}

template <>
RigidShape<3> closed_surface_shape<3>(const std::vector<Eigen::Vector3d>& nodes,
                                      std::vector<std::array<int, 3>> faces, double density,
                                      const std::string& where)
{
  require_positive(density, where + ": density");
  // Closed and consistently oriented: every directed edge once, its reverse once.
  std::map<std::pair<int, int>, int> edges;
  for (const auto& f : faces)
    for (int k = 0; k < 3; ++k)
    {
      if (f[k] < 0 || f[k] >= int(nodes.size()))
        throw InputError(where, "a triangle refers to a node that does not exist");
      ++edges[{f[k], f[(k + 1) % 3]}];
    }
  for (const auto& [edge, count] : edges)
  {
    const auto reverse = edges.find({edge.second, edge.first});
    if (count != 1 || reverse == edges.end() || reverse->second != 1)
      throw InputError(where, "the surface is not closed and consistently oriented (edge " +
                                  std::to_string(edge.first) + "-" + std::to_string(edge.second) +
                                  ")");
  }
  // Divergence theorem over the tetrahedra (0, a, b, c): volume V = a.(b x c)/6, first
  // moment V (a+b+c)/4, second moment V/20 (aa' + bb' + cc' + (a+b+c)(a+b+c)').
  double volume = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const auto& f : faces)
  {
    const Eigen::Vector3d &a = nodes[f[0]], &b = nodes[f[1]], &c = nodes[f[2]];
    const double v = a.dot(b.cross(c)) / 6;
    const Eigen::Vector3d sum = a + b + c;
    volume += v;
    first += v * sum / 4;
    second += v / 20 *
              (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
  }
  if (volume < 0)
  {
    for (auto& f : faces)
      std::swap(f[1], f[2]);
    volume = -volume, first = -first, second = -second;
  }
  if (!(volume > 0))
    throw InputError(where, "the surface encloses no volume");
  RigidShape<3> s;
  s.volume = volume;
  s.mass = density * volume;
  s.centre_of_mass = first / volume;
  const Eigen::Matrix3d c =
      density * second - s.mass * s.centre_of_mass * s.centre_of_mass.transpose();
  s.inertia = c.trace() * Eigen::Matrix3d::Identity() - c;
  s.nodes = nodes;
  s.faces = std::move(faces);
  return s;
}
} // namespace chipflex::coupling
