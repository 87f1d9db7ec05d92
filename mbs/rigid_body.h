#pragma once
// Rigid bodies are floating-frame bodies with no modes: the same mass matrix, quadratic
// velocity vector (omega x J omega), joints and integrator apply. Planar: (x, y, theta);
// spatial: position and unit quaternion.

#include "common/reduced_body_file.h"
#include "mbs/floating_frame_body.h"

#include <array>
#include <memory>
#include <vector>

namespace chipflex::mbs
{
/// Body data of a rigid body with its skin (nodes in frame coordinates; faces as in
/// SkinBody: 2D segments of a counter-clockwise outline, 3D outward triangles).
/// inertia_about_com: 2D uses the zz entry (per metre of depth), 3D the full tensor.
template <int dim>
ReducedBodyData rigid_body_data(double mass, const Eigen::Matrix<double, dim, 1>& center_of_mass,
                                const Eigen::Matrix3d& inertia_about_com,
                                const std::vector<Eigen::Matrix<double, dim, 1>>& skin_nodes,
                                const std::vector<std::array<int, dim>>& skin_faces);

/// Which ends of a chain link turn about a hinge. A flat end that turns about the middle
/// of its edge opens a wedge on one side, under the wall it hangs from or against the
/// next link, and fluid pressed into that wedge is squeezed out at several m/s when it
/// closes. A rounded end (a half circle of radius thickness / 2 about the hinge, the
/// outline of a hinge barrel) keeps the skin closed at any angle.
struct LinkEnds
{
  bool round_top = false;
  bool round_bottom = false;
  int arc_segments = 8; ///< segments per half circle (sag 1.9 % of the radius at 8)
};

/// A planar rectangular link of the rigid-chain gate: frame origin at the middle of its
/// top edge (the hinge), hanging along -y; width `thickness` in x; density per volume, so
/// the mass is per metre of depth. Its skin is the rectangle outline, with the rounded
/// ends asked for. Mass and inertia are the rectangle's: a rounded end is the outline of
/// the hinge, which half lies inside the wall or link it joins.
ReducedBodyData rectangular_link_data(double length, double thickness, double density,
                                      const LinkEnds& ends = {});

template <int dim>
std::unique_ptr<FloatingFrameBody<dim>> make_rigid_body(const ReducedBodyData& data)
{
  return std::make_unique<FloatingFrameBody<dim>>(data);
}
} // namespace chipflex::mbs
