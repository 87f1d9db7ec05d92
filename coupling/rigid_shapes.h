#pragma once
// Rigid bodies of any shape as plain data: mass, centre of mass, inertia about the centre
// of mass and the skin (nodes and faces in the body frame) that the fluid and contact
// see. Primitives (box, cylinder, sphere) carry their exact mass properties; a closed
// surface (a polygon in 2D, a triangulated surface in 3D, e.g. from a gmsh mesh, an STL
// file or a body file's skin) gets its mass properties from the divergence theorem over
// the faces, exact for the faceted solid.
//
// 2D: per metre of depth (mass kg/m, inertia kg m^2/m about z); faces are segments of a
// counter-clockwise outline. 3D: faces are triangles with outward normals.

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace chipflex::coupling
{
template <int dim>
struct RigidShape
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  double mass = 0;
  double volume = 0; ///< m^3 (2D: m^2, the area)
  Vector centre_of_mass = Vector::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero(); ///< about the centre of mass
  std::vector<Vector> nodes;
  std::vector<std::array<int, dim>> faces;
};

/// A box of edge lengths `size`, centred on the frame origin, its faces split so that
/// skin nodes lie at most `spacing` apart.
template <int dim>
RigidShape<dim> box_shape(const Eigen::Matrix<double, dim, 1>& size, double density,
                          double spacing);

/// 3D: a cylinder of `radius` and `length` along the frame's z axis, centred on the
/// origin. 2D: a disc of `radius` (`length` unused).
template <int dim>
RigidShape<dim> cylinder_shape(double radius, double length, double density, double spacing);

/// 3D: a sphere; 2D: a disc. Centred on the frame origin.
template <int dim>
RigidShape<dim> sphere_shape(double radius, double density, double spacing);

/// A closed surface (every edge shared by two faces in 3D, a closed outline in 2D) with
/// the given orientation; faces oriented inwards are flipped. Mass properties of the
/// solid it encloses. Throws InputError naming `where` if it is not closed or encloses
/// no volume.
template <int dim>
RigidShape<dim> closed_surface_shape(const std::vector<Eigen::Matrix<double, dim, 1>>& nodes,
                                     std::vector<std::array<int, dim>> faces, double density,
                                     const std::string& where);
} // namespace chipflex::coupling
