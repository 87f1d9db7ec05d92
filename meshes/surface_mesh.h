#pragma once
// Surfaces for walls and rigid bodies, read from a file: segments in 2D, triangles in 3D.
//   *.stl  3D, ASCII or binary STL (facets; coincident corners merged).
//   *.msh  gmsh mesh: the elements of dimension dim - 1 (lines in 2D, triangles and quads,
//          split in two, in 3D), of one physical group if named, else of the whole mesh.
//          A volume (3D) or surface (2D) mesh that holds no such elements gives its
//          boundary instead.
// Face orientation is the file's; `flip` reverses every face (walls need their normal on
// the fluid side). Bad files throw InputError naming the file and the problem.

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace chipflex::meshes
{
template <int dim>
struct SurfaceMesh
{
  std::vector<Eigen::Matrix<double, dim, 1>> vertices;
  std::vector<std::array<int, dim>> faces;
};

/// `group` empty: every element of dimension dim - 1 (or the boundary, see above).
template <int dim>
SurfaceMesh<dim> read_surface_mesh(const std::string& path, const std::string& group = "",
                                   bool flip = false);
} // namespace chipflex::meshes
