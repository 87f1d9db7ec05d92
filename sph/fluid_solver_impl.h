#pragma once
// Private part of FluidSolver (only its .cc files include this): neighbour grid, sort
// buffers, wall bins, equation of state and the force pass compiled for the chosen
// viscosity and density-diffusion policies.

#include "sph/density_diffusion.h"
#include "sph/dummy_wall_particles.h"
#include "sph/fluid_solver.h"
#include "sph/force_loop.h"
#include "sph/lennard_jones_wall.h"
#include "sph/neighbour_grid.h"
#include "sph/tait_equation_of_state.h"
#include "sph/thin_skins.h"
#include "sph/viscosity_models.h"
#include "sph/wendland_kernel.h"

#include <array>

namespace chipflex::sph
{
struct PairPolicies
{
  ArtificialViscosity artificial;
  LaminarViscosity laminar;
  NoDensityDiffusion no_diffusion;
  MolteniColagrossiDiffusion molteni_colagrossi;
  FourtakasDiffusion fourtakas;

  template <class T>
  const T& get() const
  {
    if constexpr (std::is_same_v<T, ArtificialViscosity>)
      return artificial;
    else if constexpr (std::is_same_v<T, LaminarViscosity>)
      return laminar;
    else if constexpr (std::is_same_v<T, NoDensityDiffusion>)
      return no_diffusion;
    else if constexpr (std::is_same_v<T, MolteniColagrossiDiffusion>)
      return molteni_colagrossi;
    else
      return fourtakas;
  }
};

template <int dim>
struct FluidSolver<dim>::Impl
{
  using PassFunction = float (*)(const ForcePassInput<dim>&, const PairPolicies&, std::size_t,
                                 std::size_t);

  NeighbourGrid<dim> grid;
  std::vector<std::uint32_t> fluid_start, boundary_start, permutation;
  std::vector<double> scratch;
  std::vector<WallAttachment<dim>> attachments; ///< by boundary particle id
  LennardJonesWalls<dim> lennard_jones;
  ThinSkins<dim> thin_skins;
  std::vector<char> wall_closed; ///< by wall: a closed thin skin
  std::vector<char> thin_dummy;  ///< by boundary particle id: a thin skin's own
  bool thin_skins_binned = false;
  /// Force of the thin skins' guard on each wall vertex in this pass (sph/thin_skins.h).
  std::vector<std::vector<Eigen::Matrix<double, dim, 1>>> guard_forces;
  std::size_t n_guarded = 0;        ///< fluid particles put back on their side so far
  std::size_t n_guarded_shared = 0; ///< over MPI: of those, the run's as last shared
  /// Boundary particles beside an open boundary's buffer in this pass: their density is
  /// prescribed like the buffer's (prescribe_open_boundaries) and kept (freeze_...).
  std::vector<std::uint32_t> walls_beside_buffers;
  /// Boundary particles whose density is taken from the fluid in this pass (walls that
  /// slide in place; sph/fluid_solver_wall_density.cc).
  std::vector<std::uint32_t> walls_from_fluid;
  /// Particle shifting (sph/particle_shifting.h), by fluid particle: the last pass's
  /// sums, read by the update right after it.
  std::array<std::vector<float>, dim> shift_sum;
  std::vector<float> position_divergence, closest;
  float inverse_w_dp = 0;
  /// 1 / sum of t^4 (5 - 4t) over a full lattice support (summation density).
  double inverse_lattice_sum = 0;
  /// Over MPI, by particle: its sums are needed on this rank (ForcePassInput::active).
  std::vector<std::uint8_t> active;
  TaitEquationOfState eos{1000, 10, 7};
  PairPolicies policies;
  PassFunction pass = nullptr;
  float kernel_factor = 0;
  float fill_factor = 0;

  /// sided: compile the pass with the thin skins' visibility mask.
  void setup(const FluidParameters<dim>& p, bool sided);
  std::size_t memory_bytes() const
  {
    return (fluid_start.capacity() + boundary_start.capacity() + permutation.capacity()) * 4 +
           scratch.capacity() * 8;
  }
};
} // namespace chipflex::sph
