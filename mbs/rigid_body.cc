#include "mbs/rigid_body.h"

#include "common/input_error.h"

#include <cmath>

namespace chipflex::mbs
{
template <int dim>
ReducedBodyData rigid_body_data(double mass, const Eigen::Matrix<double, dim, 1>& center_of_mass,
                                const Eigen::Matrix3d& inertia_about_com,
                                const std::vector<Eigen::Matrix<double, dim, 1>>& skin_nodes,
                                const std::vector<std::array<int, dim>>& skin_faces)
{
  if (mass <= 0)
    throw InputError("rigid body", "mass must be positive");
  ReducedBodyData d;
  d.dim = dim;
  d.mesh_file = "rigid body";
  d.model = "rigid";
  const int n = static_cast<int>(skin_nodes.size());
  d.nodes.resize(n, dim);
  for (int i = 0; i < n; ++i)
    d.nodes.row(i) = skin_nodes[i].transpose();
  for (int i = 0; i < n; ++i)
    d.skin_nodes.push_back(i);
  d.skin_faces.resize(static_cast<int>(skin_faces.size()), dim);
  for (std::size_t f = 0; f < skin_faces.size(); ++f)
    for (int c = 0; c < dim; ++c)
      d.skin_faces(static_cast<int>(f), c) = skin_faces[f][c];
  d.node_sets["skin"] = d.skin_nodes;
  d.psi.resize(dim * n, 0);
  d.mass_matrix.resize(0, 0);
  d.stiffness_matrix.resize(0, 0);
  d.mass = mass;
  d.center_of_mass = center_of_mass;
  d.inertia_tensor = inertia_about_com;
  // C(x, x) = m c c^T + S_c, with S_c the second moment about the centre of mass:
  // J_c = tr(S_c) I - S_c  =>  S_c = tr(J_c)/2 I - J_c (3D). In 2D only tr S_c = J_zz
  // enters the equations, so S_c = J_zz / 2 I.
  Eigen::Matrix<double, dim, dim> s_c;
  if constexpr (dim == 2)
    s_c = 0.5 * inertia_about_com(2, 2) * Eigen::Matrix2d::Identity();
  else
    s_c = 0.5 * inertia_about_com.trace() * Eigen::Matrix3d::Identity() - inertia_about_com;
  d.c_xx = mass * center_of_mass * center_of_mass.transpose() + s_c;
  d.translation_coupling.resize(dim, 0);
  return d;
}

ReducedBodyData rectangular_link_data(double length, double thickness, double density,
                                      const LinkEnds& ends)
{
  if (length <= 0 || thickness <= 0 || density <= 0)
    throw InputError("rectangular link", "length, thickness and density must be positive");
  if ((ends.round_top || ends.round_bottom) && ends.arc_segments < 2)
    throw InputError("rectangular link", "a rounded end needs at least 2 arc segments");
  const double mass = density * length * thickness;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  inertia(2, 2) = mass * (length * length + thickness * thickness) / 12.0;
  const double h = 0.5 * thickness;
  // Counter-clockwise outline (outward normals (dy, -dx)): bottom edge left to right, up
  // the right side, over the top, down the left side. A rounded end replaces its edge by
  // the half circle about the hinge, from angle a0 to a0 + pi.
  std::vector<Eigen::Vector2d> nodes;
  const auto half_circle = [&](const Eigen::Vector2d& centre, double a0)
  {
    for (int k = 1; k < ends.arc_segments; ++k)
    {
      const double a = a0 + M_PI * k / ends.arc_segments;
      nodes.push_back(centre + h * Eigen::Vector2d(std::cos(a), std::sin(a)));
    }
  };
  nodes.push_back({-h, -length});
  if (ends.round_bottom)
    half_circle({0.0, -length}, M_PI);
  nodes.push_back({h, -length});
  nodes.push_back({h, 0.0});
  if (ends.round_top)
    half_circle({0.0, 0.0}, 0.0);
  nodes.push_back({-h, 0.0});
  const int n = static_cast<int>(nodes.size());
  std::vector<std::array<int, 2>> faces;
  for (int i = 0; i < n; ++i)
    faces.push_back({i, (i + 1) % n});
  ReducedBodyData d =
      rigid_body_data<2>(mass, Eigen::Vector2d(0.0, -0.5 * length), inertia, nodes, faces);
  const int bottom_right = ends.round_bottom ? ends.arc_segments : 1;
  d.node_sets["tip"] = {0, bottom_right};
  d.node_sets["clamp"] = {bottom_right + 1, n - 1};
  return d;
}

template ReducedBodyData rigid_body_data<2>(double, const Eigen::Vector2d&, const Eigen::Matrix3d&,
                                            const std::vector<Eigen::Vector2d>&,
                                            const std::vector<std::array<int, 2>>&);
template ReducedBodyData rigid_body_data<3>(double, const Eigen::Vector3d&, const Eigen::Matrix3d&,
                                            const std::vector<Eigen::Vector3d>&,
                                            const std::vector<std::array<int, 3>>&);
} // namespace chipflex::mbs
