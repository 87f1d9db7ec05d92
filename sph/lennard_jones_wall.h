#pragma once
// The seed paper's modified Lennard-Jones wall (docs/sph.md, Walls), per unit particle mass:
//   F(d) = k ((R-d)^4 - (R-r0)^2 (R-d)^2) / (R^2 r0 (2R - r0))  for 0 <= d <= R,
// F(0) = k, F(r0) = 0, slightly attractive between r0 and R, zero beyond. It acts along
// the face normal on fluid particles whose foot point lies on the face; a particle that
// has crossed the face by less than R is pushed back with F(0) = k.
//
// Defaults (derive_lennard_jones):
//   r0 = dp/2: a lattice filled against a wall starts half a spacing from it, so the
//              initial state is in equilibrium;
//   R  = dp:   one particle layer feels the wall;
//   k  = 10 p_e / (rho0 dp): a wall particle carries the pressure p of its column
//              slice, m F = p dp^(dim-1), i.e. F = p / (rho0 dp). Ten times the expected
//              pressure p_e keeps it within ~10 % of r0, and the energy barrier
//              ~ k r0 / 2 = 5 p_e / rho0 stops particles arriving at the speed
//              sqrt(p_e / rho0). p_e defaults to rho0 (c0/10)^2 (c0 is ten times the
//              fastest expected flow speed, and for c0 = 10 sqrt(g H) it is rho0 g H).
//
// Faces are binned into the neighbour cells their R-expanded box overlaps, so each
// particle only tests the faces of its own cell. Faces in one plane (a triangulated
// flat wall, collinear segments) act once on a particle even at shared edges.

#include "sph/face_bins.h"
#include "sph/neighbour_grid.h"
#include "sph/particle_arrays.h"
#include "sph/wall_surface.h"

#include <array>
#include <cstdint>
#include <vector>

namespace chipflex::sph
{
struct LennardJonesForce
{
  explicit LennardJonesForce(const LennardJonesParameters& p)
      : k(p.k), R(p.R), r0(p.r0), scale(p.k / (p.R * p.R * p.r0 * (2 * p.R - p.r0)))
  {
  }
  double operator()(double d) const
  {
    if (d >= R)
      return 0;
    const double u = std::max(R - std::max(d, 0.0), 0.0), u2 = u * u;
    return scale * (u2 * u2 - (R - r0) * (R - r0) * u2);
  }
  double k, R, r0, scale;
};

/// Fills zero entries of `given` with the defaults above; checks 0 < r0 < R.
LennardJonesParameters derive_lennard_jones(LennardJonesParameters given, double dp, double rho0,
                                            double expected_pressure, const std::string& wall_name);

template <int dim>
class LennardJonesWalls
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;

  /// Bins the faces of the walls that act on the fluid by this model (others: nullptr).
  void bin(const std::vector<const WallSurface<dim>*>& walls, const NeighbourGrid<dim>& grid);

  /// Adds the wall accelerations to fluid particles [first, last) (their `cell` must be
  /// current) and the reactions, distributed with the foot-point weights, to
  /// vertex_forces[wall][vertex]. The summation order is the particle order, whatever
  /// the thread count.
  void apply(ParticleArrays<dim>& p, std::size_t first, std::size_t last, double mass,
             std::vector<std::vector<Vector>>& vertex_forces) const;

  bool empty() const { return bins_.faces.empty(); }

private:
  struct Contribution
  {
    std::uint32_t wall, face;
    std::array<double, dim> weights;
    Vector force; ///< on the particle
  };
  std::vector<const WallSurface<dim>*> walls_;
  std::vector<LennardJonesForce> forces_;
  FaceBins<dim> bins_;
};
} // namespace chipflex::sph
