#pragma once
// Particle shifting: after each step every fluid particle moves by
//   dr_i = -D sum_j V_j [1 + R (W_ij / W(dp))^n] grad_i W_ij,   R = 0.2, n = 4,
//   D = A h |v_i| dt,  A = 2,
// Fickian shifting (Lind et al. 2012, J. Comput. Phys. 231) with the diffusion
// coefficient of Skillen et al. (2013, Comput. Methods Appl. Mech. Eng. 265), as
// DualSPHysics uses it (its shifting coefficient -2), and the tensile term of Sun et al.'s
// delta+-SPH (2017, J. Comput. Phys. 333). The sum is the gradient of the particle
// concentration: a particle drifts from where particles crowd to where they are sparse,
// so the particles stay near a regular lattice instead of lining up along streamlines and
// leaving gaps (the voids that open behind bodies in an internal flow), and the tensile
// term pushes pairs that come closer than dp apart. D grows with the particle's own speed,
// so a fluid at rest is not touched. (Sun et al.'s D = CFL Ma (2h)^2 with the flow's
// reference speed acts at rest too: it moved a hydrostatic tank's pressure by up to 0.85 %
// and lifted its surface by 0.07 dp here.)
//
// At a free surface the concentration gradient points into the fluid, and the shift
// would carry the surface particles outwards. The divergence of the position,
//   div_i r = -sum_j V_j F_ij r_ij^2   (dim inside the fluid, about half that on a surface),
// finds them (Lind et al. 2012, J. Comput. Phys. 231): below dim - 0.25 a particle is not
// shifted (DualSPHysics' free-surface threshold in 3D; dim - 0.5 left the second row of a
// 2D tank's surface shifted outwards). Keeping the part
// along the surface, as Lind et al. and Sun et al. do, needs a normal independent of the
// shift itself (the shift is parallel to the concentration gradient, so the projection
// leaves nothing). A Lennard-Jones wall, which has no dummy particles, reads as a free
// surface too, so the fluid is not shifted into it.
// The shift is capped at a tenth of the spacing per step.
//
// The sums come from the step's last force pass (sph/force_loop.h gathers them beside
// the pressure force at little extra cost, as DualSPHysics does); the shift is applied
// after the step's position update.

#include <cmath>

namespace chipflex::sph
{
/// The shift of one fluid particle from its force-pass sums: `sum` the concentration
/// gradient's sum (dim values), `divergence` div r, `diffusion` D (m^2), `cap` the largest
/// shift (m). Writes `shift` (dim values).
template <int dim>
inline void particle_shift(const float* sum, float divergence, float diffusion, float cap,
                           double* shift)
{
  double dr[dim], len2 = 0;
  for (int d = 0; d < dim; ++d)
  {
    dr[d] = -double(diffusion) * double(sum[d]);
    len2 += dr[d] * dr[d];
  }
  const double len = std::sqrt(len2);
  const double scale =
      divergence < float(dim) - 0.25f ? 0.0 : (len > double(cap) ? double(cap) / len : 1.0);
  for (int d = 0; d < dim; ++d)
    shift[d] = scale * dr[d];
}
} // namespace chipflex::sph
