#pragma once
// Dummy (boundary) particles of a wall, the field's usual alternative to a wall force:
// layers of particles behind the surface whose density follows the continuity equation
// and whose pressure then repels the fluid (dynamic boundary condition, Crespo et al.
// 2007, as in DualSPHysics). Each dummy particle is attached to one face by its
// barycentric weights and its offset along the normal: moving the vertices moves it
// rigidly with the face, and the fluid's force on it goes back to the vertices with
// the same weights (momentum conserving, the moment too for a rigid face).

#include "sph/wall_surface.h"

#include <array>
#include <cstdint>
#include <vector>

namespace chipflex::sph
{
template <int dim>
struct WallAttachment
{
  static constexpr std::uint32_t no_wall = 0xffffffffu;
  std::uint32_t wall = no_wall, face = 0;
  std::array<double, dim> weights{};
  double offset = 0;
};

/// Layers at offsets -(l + 1/2) dp behind every face (l < layers), dp apart along the
/// face; points closer than dp/2 to an earlier one (convex corners) are dropped.
template <int dim>
std::vector<Eigen::Matrix<double, dim, 1>> generate_dummy_particles(const WallSurface<dim>& wall,
                                                                    double dp, int layers);

/// Attaches a point to the face whose plane it is nearest to among the faces its
/// foot point falls on (or, failing that, the nearest face centre).
template <int dim>
WallAttachment<dim> attach_to_wall(const WallSurface<dim>& wall, std::uint32_t wall_id,
                                   const Eigen::Matrix<double, dim, 1>& x);

/// Position and velocity of an attached particle for the wall's current vertices.
template <int dim>
void attached_state(const WallSurface<dim>& wall, const WallAttachment<dim>& a,
                    Eigen::Matrix<double, dim, 1>& x, Eigen::Matrix<double, dim, 1>& v);
} // namespace chipflex::sph
