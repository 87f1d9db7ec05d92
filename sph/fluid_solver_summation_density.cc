// FluidSolver: the fluid's density moved towards its kernel sum (FluidParameters::
// summation_blend): in every force pass, rho_i += b (rho0 S_i / S_lattice - rho_i), where
// S_i = sum_j t^4 (5 - 4t) is the Wendland kernel summed over particle i's support (fluid
// and boundary particles, the force loop's thin-skin mask) and S_lattice the same sum over
// a full lattice, so a particle on the starting lattice reads rho0.
//
// Why: in an internal flow the continuity density and the particles' spacing drift apart.
// An outlet that removes a little more than the inlet brings (after the start, behind a
// wake) leaves fewer particles in the channel, yet each keeps its density and its
// pressure: nothing sees the deficit, nothing draws fluid back, and the particles spread
// until the channel has lost a tenth of its fluid (the Re-100 cylinder at D/10 with no
// background pressure: 11.7 % in 2 s). With the kernel sum the density falls where the
// particles spread, the pressure with it, and the outlet's pressure pushes fluid back in
// (SPHinXsys takes the density of internal flows by summation). The plain sum (b = 1)
// turns a starting lattice's misfit beside a curved wall (a few per cent) into a pressure
// kick at the first step, which blew the D/10 cylinder up within 0.02 s; a fraction per
// step (b = 0.1: about 10 steps, far less than the flow's time) lets it settle.
// Internal flows only: a free surface's truncated support reads as sparse. Buffer particles
// keep what their boundary sets, wall particles their own density; ghosts are summed by
// their owner. Both time levels move by the same amount, so the Verlet scheme's leapfrog
// pair stays consistent.

#include "sph/fluid_solver_impl.h"

#include <cmath>

namespace chipflex::sph
{
template <int dim>
void FluidSolver<dim>::sum_densities()
{
  auto& p = particles_;
  auto& im = *impl_;
  const std::size_t nb = p.n_boundary, n = p.size();
  const double inv_2h = 0.5 / h_, support2 = 4 * h_ * h_;
  const double rho_per_sum = parameters_.reference_density * im.inverse_lattice_sum;
  const bool sided = !p.skin.empty();
  const double blend = parameters_.summation_blend;
  // Each particle writes its own density and reads positions only: any order, same result.
#pragma omp parallel for schedule(dynamic, 256) if (n - nb > light_parallel_threshold)
  for (std::size_t i = nb; i < n; ++i)
  {
    if ((!p.zone.empty() && p.zone[i] != 0) || p.is_ghost(i))
      continue;
    double xi[dim];
    for (int d = 0; d < dim; ++d)
      xi[d] = p.position[d][i];
    const float ski = sided ? p.skin[i] : 0.0f;
    double sum = 0;
    const std::int64_t c = p.cell[i];
    for (int r = 0; r < NeighbourGrid<dim>::n_rows; ++r)
    {
      const std::int64_t base = c + im.grid.row_offsets()[r];
      // Fluid neighbours, then boundary ones: the force loop's two ranges and masks.
      for (int kind = 0; kind < 2; ++kind)
      {
        const auto& start = kind == 0 ? im.fluid_start : im.boundary_start;
        const float cut = kind == 0 ? -0.5f : 0.5f;
        for (std::uint32_t j = start[base]; j < start[base + 3]; ++j)
        {
          double r2 = 0;
          for (int d = 0; d < dim; ++d)
          {
            const double dx = xi[d] - p.position[d][j];
            r2 += dx * dx;
          }
          if (r2 >= support2)
            continue;
          if (ski > 0.0f && p.skin[j] == ski)
          {
            float facing = 0;
            for (int d = 0; d < dim; ++d)
              facing += p.side[d][i] * p.side[d][j];
            if (facing < cut)
              continue;
          }
          const double t = 1 - inv_2h * std::sqrt(r2);
          sum += t * t * t * t * (5 - 4 * t);
        }
      }
    }
    const float change = float(blend * (rho_per_sum * sum - p.density[i]));
    p.density[i] += change;
    p.density_previous[i] += change;
  }
}

template void FluidSolver<2>::sum_densities();
template void FluidSolver<3>::sum_densities();
} // namespace chipflex::sph
