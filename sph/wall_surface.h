#pragma once
// A wall the fluid feels, given as a surface mesh: segments in 2D, triangles in 3D.
// This is the interface through which bodies load the fluid and the fluid loads bodies
// (coupling/): each step the owner moves the vertices, the solver computes the fluid
// forces, and reports the reaction on every vertex, distributed with the same weights
// (barycentric on the face) that placed the contact point, so that the momentum the
// fluid loses is exactly the momentum the wall gains.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace chipflex::sph
{
enum class WallModel
{
  lennard_jones,   ///< the seed paper's modified Lennard-Jones force (docs/sph.md)
  dummy_particles, ///< layers of dummy particles that move with the surface
  /// A skin of any thickness down to zero (an open polyline or surface, or a closed
  /// skin thinner than the kernel) with fluid on one or both sides: sided dummy
  /// particles and a visibility mask (sph/thin_skins.h, docs/sph.md "Thin skins").
  thin_skin
};

inline const char* wall_model_name(WallModel model)
{
  return model == WallModel::lennard_jones     ? "Lennard-Jones"
         : model == WallModel::dummy_particles ? "dummy-particle"
                                               : "thin-skin";
}

/// Parameters of the modified Lennard-Jones wall force
///   F(d) = k ((R-d)^4 - (R-r0)^2 (R-d)^2) / (R^2 r0 (2R - r0))  for d <= R, else 0,
/// per unit of particle mass (an acceleration, m/s^2) acting along the wall normal.
struct LennardJonesParameters
{
  double k = 0;  ///< force scale F(0) (0: derive from spacing and expected pressure)
  double R = 0;  ///< cut-off distance (0: derive from the particle spacing)
  double r0 = 0; ///< equilibrium distance, F(r0) = 0 (0: derive from the particle spacing)
};

/// One face of one wall: the wall's index in the list searched, the face's index in it.
struct WallFace
{
  std::uint32_t wall, face;
};

template <int dim>
struct WallSurface
{
  using Vector = Eigen::Matrix<double, dim, 1>;

  std::string name;
  WallModel model = WallModel::lennard_jones;
  LennardJonesParameters lennard_jones;
  /// Vertex positions and velocities in world coordinates.
  std::vector<Vector> vertices;
  std::vector<Vector> velocities;
  /// Vertex ids of each face. The fluid lies on the side of the face normal:
  /// 2D: (a, b) with normal (dy, -dx), (dx, dy) = b - a, i.e. the fluid is on the RIGHT
  /// of a -> b (the outward normal of a body traversed counter-clockwise; a tank is
  /// traversed clockwise); 3D: (a, b, c) with normal (b - a) x (c - a).
  std::vector<std::array<int, dim>> faces;
  /// A permeable barrier: bodies feel it, the fluid does not (coupling/ only).
  bool fluid_passes = false;
  /// The surface moves along itself and keeps its place (a turning borehole wall): its
  /// velocities are tangential and its dummy particles stay where they are, so their
  /// density is taken from the fluid, not from the continuity sum (docs/sph.md, "Walls that
  /// slide in place").
  bool slides_in_place = false;
  /// A body's skin, which FluidSolver::move_wall moves (coupling/). A wall that does not
  /// move keeps its faces: over MPI the halo counts its normals (exchange_halo_needs).
  bool moves = false;
  /// dummy_particles: layers behind the surface (0: enough to cover the kernel support).
  int dummy_layers = 0;
};
} // namespace chipflex::sph
