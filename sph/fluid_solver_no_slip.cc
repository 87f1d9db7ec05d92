// FluidSolver: no-slip dummy walls (FluidParameters::no_slip_walls). The dynamic boundary
// condition gives a wall particle the wall's velocity; the fluid's viscous stress then
// sees a no-slip surface near the first dummy layer, half a spacing behind the face, and
// plane Poiseuille flow at 20 particles across runs 6 % slow at the centre and twice too
// fast next to the wall (docs/sph.md, "Open boundaries"). With the option each dummy
// particle gets 2 v_wall - v_g, v_g the fluid's velocity at its mirror point across the
// face (a first-order moving-least-squares fit, sph/mirror_fit.h): the velocity field
// through the wall is antisymmetric about the face, which is where it vanishes. This is
// the no-slip velocity of the modified dynamic boundary condition (English, Dominguez,
// Vacondio, Crespo, Stansby, Lind, Chiapponi & Gomez-Gesteira, Comp. Part. Mech. 9 (2022)
// 1-15); the density keeps its dynamic-boundary evolution. Outside the force loop, after
// each sort.

#include "sph/fluid_solver_impl.h"
#include "sph/mirror_fit.h"
#include "sph/wall_geometry.h"

namespace chipflex::sph
{
template <int dim>
void FluidSolver<dim>::mirror_wall_velocities()
{
  auto& p = particles_;
  auto& im = *impl_;
  const WendlandKernel<dim> W(h_);
  // Each wall particle reads fluid particles only: any order gives the same result.
  for (std::size_t i = 0; i < p.n_boundary; ++i)
  {
    const auto& a = im.attachments[p.id[i]];
    if (a.wall == WallAttachment<dim>::no_wall)
      continue;
    const auto& wall = walls_[a.wall];
    Vector x, v_wall;
    attached_state(wall, a, x, v_wall);
    const Vector xg = point_on_face(wall, int(a.face), a.weights, -a.offset);
    const auto fit = fit_at<dim>(p, im.grid, im.fluid_start, W, mass_, xg, false);
    const Vector v = fit.valid ? Vector(2 * v_wall - fit.velocity) : v_wall;
    for (int d = 0; d < dim; ++d)
      p.velocity[d][i] = float(v[d]);
  }
}

template void FluidSolver<2>::mirror_wall_velocities();
template void FluidSolver<3>::mirror_wall_velocities();
} // namespace chipflex::sph
