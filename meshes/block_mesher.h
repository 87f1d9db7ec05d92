#pragma once
// Generator for the straight bodies chipflex meshes: a rectangle (2D) or a box (3D) with
// one long axis, clamped at one end. Gates and plates are such blocks.
//
// Physical groups written (gmsh .msh 4.1, names kept):
//   body  (dim)    the whole block
//   clamp (dim-1)  the clamped end face/edge
//   tip   (dim-1)  the free end face/edge, opposite the clamp
//   skin  (dim-1)  the whole boundary (overlaps clamp and tip)
//   xmin, xmax, ymin, ymax (, zmin, zmax)  (dim-1)  each side by position, e.g. xmin is
//                  the side at x = 0 (overlapping the groups above)

#include <array>
#include <string>

namespace chipflex::meshes
{
struct BlockMeshSpec
{
  int dim = 2;                              ///< 2 or 3
  std::array<double, 3> extent{0., 0., 0.}; ///< m, along x, y, z (z unused in 2D)
  int long_axis = 1;                        ///< 0, 1 or 2: the clamp-tip axis
  bool clamp_at_max = true;                 ///< clamp at the high end of the long axis
  double size = 0.;                         ///< target element edge length, m
  bool simplex = false;                     ///< triangles/tets (unstructured) instead of
                                            ///< structured quads/hexes
};

/// Meshes the block and writes it atomically to `path` (gmsh .msh 4.1).
/// Returns the number of elements of dimension `dim`.
std::size_t write_block_mesh(const BlockMeshSpec& spec, const std::string& path);
} // namespace chipflex::meshes
