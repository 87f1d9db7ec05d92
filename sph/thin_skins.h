#pragma once
// Thin skins: walls of any thickness down to zero (an open polyline or surface, a chip
// thinner than the kernel support) with fluid on one or both sides (docs/sph.md, "Thin
// skins"). Three parts:
//
//  * Sides. Every fluid particle within reach of a thin skin (2h plus the dummy layers'
//    depth) carries the unit vector from the skin's nearest point to itself, and the
//    skin's id; a dummy particle carries the normal of the face it serves. A pair of one
//    skin's opposite sides (side_i . side_j < -1/2) is masked out of every sum of the
//    force pass (sph/force_loop.h): no interaction passes through the skin.
//  * Sided dummy particles. Each face gets layers of dummy particles behind it for the
//    fluid in front of it, and an open skin the same in front of it for the fluid behind
//    it. A layer may lie among the other side's fluid: the mask keeps them apart, so the
//    kernel support of a particle next to the skin is full on either side, whatever the
//    thickness, and each side's pressure loads the skin through its own dummy particles.
//  * A guard. A fluid particle whose side turns over across a face between two force
//    passes (it crossed the skin, or the skin swept past it) is put back a quarter of a
//    spacing in front of the face on its old side, its velocity relative to the face
//    stripped of its normal approach; the momentum that takes goes to the face's
//    vertices, so the exchange stays momentum conserving.

#include "sph/dummy_wall_particles.h"
#include "sph/face_bins.h"
#include "sph/face_tree.h"
#include "sph/neighbour_grid.h"
#include "sph/particle_arrays.h"
#include "sph/wall_geometry.h"
#include "sph/wall_surface.h"

#include <cstdint>
#include <vector>

namespace chipflex::sph
{
/// True when every vertex (2D) or edge (3D) of the skin is shared by exactly two faces.
template <int dim>
bool is_closed(const WallSurface<dim>& wall);

/// Thickness of a skin: 0 for an open one, else the shortest distance from a face's
/// centre straight back (along -normal) to another face of the skin.
template <int dim>
double skin_thickness(const WallSurface<dim>& wall);

/// Dummy particles of a thin skin, attached to the faces that made them: layers at
/// -(l + 1/2) dp behind every face (they serve its front) and, for an open skin, at
/// +(l + 1/2) dp (they serve its back); points closer than dp/2 to an earlier one
/// serving the same side are dropped.
template <int dim>
std::vector<WallAttachment<dim>> generate_thin_skin_dummies(const WallSurface<dim>& wall,
                                                            std::uint32_t wall_id, double dp,
                                                            int layers);

template <int dim>
class ThinSkins
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;

  /// Bins the faces of the thin-skin walls (others: nullptr) into the cells within
  /// `reach` of them; closed[w]: wall w is a closed skin (is_closed). Sides within
  /// `exact_distance` of a skin come from the exact nearest point. Call after the walls
  /// moved.
  void bin(const std::vector<const WallSurface<dim>*>& walls, const std::vector<char>& closed,
           const NeighbourGrid<dim>& grid, double reach, double exact_distance);
  bool empty() const { return bins_.faces.empty(); }

  /// Sides of fluid particles [first, last) for their current positions (computed with
  /// the grid, not p.cell: called before the sort); puts back the particles whose side
  /// turned over across a face (see above) and adds the momentum that took, divided by
  /// dt, to guard_forces[wall][vertex] (the force on the skin). Deterministic: the put-
  /// backs are applied in particle order. Returns how many were put back.
  std::size_t label_fluid(ParticleArrays<dim>& p, std::size_t first, std::size_t last,
                          const NeighbourGrid<dim>& grid, double guard_distance, double mass,
                          double dt, std::vector<std::vector<Vector>>& guard_forces);

  /// Sides of the boundary particles [0, n_boundary) that belong to no thin skin
  /// (a tank's dummy layers that a thin skin dips into must not act across it either):
  /// as for fluid particles, without the guard. is_own[id]: boundary particle id is a
  /// thin skin's dummy particle (it keeps the side of its face).
  void label_boundary(ParticleArrays<dim>& p, const NeighbourGrid<dim>& grid,
                      const std::vector<char>& is_own) const;

private:
  using Face = WallFace;

  /// The thin-skin face nearest to x and its nearest point; false when x is out of every
  /// skin's reach (no face binned in x's cell).
  bool nearest_face(const NeighbourGrid<dim>& grid, const Vector& x, Face& best,
                    ClosestPoint<dim>& closest) const;

  std::vector<const WallSurface<dim>*> walls_;
  std::vector<char> closed_;
  FaceBins<dim> bins_;
  FaceTree<dim> tree_;
  double exact_distance_ = 0;
  std::vector<std::uint8_t> crossed_;
};

/// Side and skin of a thin skin's dummy particle for the wall's current vertices.
template <int dim>
void dummy_side(const WallSurface<dim>& wall, const WallAttachment<dim>& a, float (&side)[dim],
                float& skin);
} // namespace chipflex::sph
