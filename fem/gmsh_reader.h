#pragma once
// Reads a gmsh mesh file through the gmsh API (not deal.II's GridIn, which rejects one
// surface in several physical groups and has no group names). The result is plain data;
// ElasticBody builds the deal.II triangulation and the named node sets from it.

#include <array>
#include <map>
#include <string>
#include <vector>

namespace chipflex::fem
{
struct GmshMeshData
{
  std::string path;
  int dim = 0;          ///< highest element dimension: 2 or 3
  bool simplex = false; ///< triangles/tetrahedra (true) or quads/hexahedra (false)
  /// Vertices used by the body's cells, renumbered 0..n-1 (z = 0 in 2D).
  std::vector<std::array<double, 3>> vertices;
  /// Body cells: corner vertex ids in gmsh's order.
  std::vector<std::vector<unsigned int>> cells;
  /// Geometry order of the body cells: 1 (straight-sided) or 2 (complete second-order
  /// cells: 6-node triangles, 9-node quadrilaterals, 10-node tetrahedra, 27-node
  /// hexahedra). The FE degree is chosen by `reduce`, independently.
  unsigned int order = 1;
  /// False for incomplete second-order cells (8-node quadrilaterals, 20-node hexahedra):
  /// their geometry can only be used straight-sided (`reduce --straight-sided`).
  bool complete_second_order = true;
  /// Order 2: the position of each second-order node, keyed by the sorted vertex ids of
  /// the edge, face or cell whose middle it is (one node per such sub-entity).
  std::map<std::vector<unsigned int>, std::array<double, 3>> midpoint_nodes;
  /// Physical groups of dimension dim-1: name -> faces, each as its corner vertex ids.
  std::map<std::string, std::vector<std::vector<unsigned int>>> face_groups;
  /// Physical groups of dimension dim: name -> cell indices.
  std::map<std::string, std::vector<unsigned int>> cell_groups;

  /// Throws InputError unless `name` is a physical group of dimension dim-1 or dim.
  void require_group(const std::string& name, const std::string& why) const;
};

/// Throws InputError (naming the file) for a missing, malformed or truncated file, a
/// mesh without 2D/3D cells, mixed cell kinds or orders, cells of order above 2, or faces
/// of a group not on the body.
GmshMeshData read_gmsh_mesh(const std::string& path);
} // namespace chipflex::fem
