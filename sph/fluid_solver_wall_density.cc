// FluidSolver: dummy wall particles whose density is taken from the fluid instead of
// their own continuity sum. A dynamic-boundary wall particle integrates
//   d rho_w / dt = sum_j m_j (v_w - v_j) . grad W_wj
// over its fluid neighbours, which is right for a wall whose particles move with its
// velocity. A wall that slides in place (a turning borehole wall,
// WallSurface::slides_in_place) breaks that: its particles carry the surface's tangential
// velocity but never move, so wherever the fluid beside them is not spread evenly along
// the motion (where the borehole meets the flute's flanks) the sum keeps one sign and the
// density grows without end. The 3D drill flute's borehole wall stood 10 ... 50 kPa
// above its coolant within 20 ms, pushed the coolant off it, and the flute tore (a
// quarter of its fluid gone; docs/sph.md, "Walls that slide in place").
// Their density is the fluid's at the particle's mirror point across the face (a
// first-order moving-least-squares fit, sph/mirror_fit.h, as the modified dynamic
// boundary condition of English, Dominguez, Vacondio, Crespo, Stansby, Lind, Chiapponi &
// Gomez-Gesteira, Comp. Part. Mech. 9 (2022) 1-15, takes it) plus the hydrostatic step
// to the particle, rho_w = rho_g + rho0 g . (x_w - x_g) / c0^2 (Adami, Hu & Adams 2012,
// J. Comput. Phys. 231, 7057-7075). Extrapolating with the fit's own gradient instead
// overshot where few fluid particles stand (the flute's corners: 90 kPa against the
// coolant's 1 kPa). A particle with no fluid around its mirror point takes the
// reference density (it touches no fluid either). Outside the force loop, after each
// sort; the particles' rates are zeroed after the pass, so the time schemes keep the
// value.

#include "sph/fluid_solver_impl.h"
#include "sph/mirror_fit.h"
#include "sph/wall_geometry.h"

#include <algorithm>

namespace chipflex::sph
{
template <int dim>
void FluidSolver<dim>::collect_walls_from_fluid()
{
  auto& p = particles_;
  auto& im = *impl_;
  im.walls_from_fluid.clear();
  auto from_fluid = [](const WallSurface<dim>& w)
  { return w.slides_in_place && w.model == WallModel::dummy_particles; };
  if (std::none_of(walls_.begin(), walls_.end(), from_fluid))
    return;
  for (std::size_t i = 0; i < p.n_boundary; ++i)
  {
    const auto& a = im.attachments[p.id[i]];
    if (a.wall != WallAttachment<dim>::no_wall && from_fluid(walls_[a.wall]))
      im.walls_from_fluid.push_back(std::uint32_t(i));
  }
}

template <int dim>
void FluidSolver<dim>::extrapolate_wall_densities()
{
  auto& p = particles_;
  auto& im = *impl_;
  const WendlandKernel<dim> W(h_);
  const double rho_lo = parameters_.minimum_density_ratio * parameters_.reference_density;
  const double rho_hi = parameters_.maximum_density_ratio * parameters_.reference_density;
  const double rho0 = parameters_.reference_density;
  const double hydrostatic = rho0 / (parameters_.speed_of_sound * parameters_.speed_of_sound);
  const auto& list = im.walls_from_fluid;
  // Each wall particle reads fluid particles only: any order gives the same result.
#pragma omp parallel for schedule(static) if (list.size() > light_parallel_threshold)
  for (std::size_t k = 0; k < list.size(); ++k)
  {
    const std::uint32_t i = list[k];
    const auto& a = im.attachments[p.id[i]];
    const auto& wall = walls_[a.wall];
    Vector x;
    for (int d = 0; d < dim; ++d)
      x[d] = p.position[d][i];
    const Vector xg = point_on_face(wall, int(a.face), a.weights, -a.offset);
    const auto fit = fit_at<dim>(p, im.grid, im.fluid_start, W, mass_, xg, false);
    const double rho = fit.valid
                           ? std::clamp(fit.density + hydrostatic * parameters_.gravity.dot(x - xg),
                                        rho_lo, rho_hi)
                           : rho0;
    p.density[i] = p.density_previous[i] = float(rho);
  }
}

template void FluidSolver<2>::collect_walls_from_fluid();
template void FluidSolver<3>::collect_walls_from_fluid();
template void FluidSolver<2>::extrapolate_wall_densities();
template void FluidSolver<3>::extrapolate_wall_densities();
} // namespace chipflex::sph
