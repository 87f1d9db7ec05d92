#pragma once
// The hot loop: per-particle gather over the neighbour rows, no atomics, no virtual
// calls, no option branches. Viscosity and density-diffusion policies are template
// arguments (selected once per run in fluid_solver_forces.cc). Out-of-support pairs and
// the particle itself contribute exactly zero through the kernel factor and r_ij = 0,
// so the inner loop is branch-free and vectorises (`omp simd`, float arithmetic).
//
// Equations (i fluid; j fluid or boundary; grad_i W_ij = F(r) r_ij, F < 0):
//   dv_i/dt   = -sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2 + Pi_ij) F r_ij + viscous + g
//   drho_i/dt =  sum_j m_j F v_ij.r_ij + density diffusion (fluid j only)
// A boundary (dummy) particle gathers the same sums over fluid neighbours: its density
// rate (dynamic boundary condition, Crespo et al. 2007) and, as its "acceleration", the
// reaction of the fluid on it per unit of its mass (exactly opposite pair by pair).
// Every particle also counts the particles in its kernel support (itself included),
// relative to a full lattice support: the filling, 1 inside the fluid or at a wall, 0.6
// on a flat free surface, 2/21 for a pair however close (2D, h = sqrt(2) dp). It tells
// spray from fluid; counted only where the spray treatment is on (count_fill).
// With thin skins (sided, sph/thin_skins.h) a pair near one skin (skin_i = skin_j != 0)
// is masked out of every sum unless its sides agree: side_i . side_j >= -1/2 for two
// fluid particles (not on opposite sides), >= 1/2 for a fluid and a boundary particle
// (the dummy particle serves the fluid particle's side, not a face beside it).
// With particle shifting (sph/particle_shifting.h) a fluid particle also gathers the
// concentration gradient sum_j V_j [1 + R (W_ij/W(dp))^4] F r_ij, the divergence of the
// position -sum_j V_j F r_ij^2 (V_j = m / rho0 for a boundary particle), and its closest
// fluid neighbour's distance.

#include "sph/density_diffusion.h"
#include "sph/neighbour_grid.h"
#include "sph/particle_arrays.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace chipflex::sph
{
template <int dim>
struct ForcePassInput
{
  const double* x[dim];
  const float* v[dim];
  const float* rho;
  const float* pressure_term;
  const float* volume;
  const std::uint32_t* cell;
  const std::uint32_t* fluid_start;
  const std::uint32_t* boundary_start;
  const std::int64_t* rows;
  float inverse_h, kernel_factor;
  float fill_factor; ///< 1 / (particles in a full lattice support)
  float mass_fluid, mass_boundary;
  const float* side[dim]; ///< sided only
  const float* skin;      ///< sided only
  float* a[dim];
  float* density_rate;
  float* fill;
  // Particle shifting only, by fluid particle (index i - n_boundary):
  float inverse_w_dp; ///< W(t)/W(dp) = t^4 (5 - 4t) * this, t = 1 - r/(2h)
  /// A boundary particle's volume in the concentration, m / rho0: its dynamic density
  /// is the wall's pressure, not its spacing, and a wall squeezed to a higher density
  /// would otherwise read as sparse and draw the fluid into it.
  float boundary_volume;
  float* shift_sum[dim];      ///< the concentration gradient's sum
  float* position_divergence; ///< div r
  float* closest;             ///< the closest fluid neighbour's squared distance
  /// Over MPI (null otherwise): 0 for a particle whose sums no owned particle needs (a
  /// ghost, a wall particle beyond a cell of the rank's slab); its results are left
  /// as they are.
  const std::uint8_t* active = nullptr;
};

namespace detail
{
/// acc: acceleration (3), density rate, filling count, shifting sums (3) and div r;
/// acc_min: the closest fluid neighbour's squared distance (the particle itself excluded).
template <int dim, bool neighbour_is_fluid, bool count_fill, bool sided, bool shifting,
          class Viscosity, class Diffusion>
inline void gather(const ForcePassInput<dim>& in, const Viscosity& visc, const Diffusion& diff,
                   std::uint32_t jb, std::uint32_t je, const double (&xi)[3], const float (&vi)[3],
                   float rhoi, float pti, const float (&si)[4], float min_facing, float mj,
                   float (&acc)[9], float& acc_min, float& dot_rr2_max)
{
  const float* const s0 = sided ? in.side[0] : nullptr;
  const float* const s1 = sided ? in.side[1] : nullptr;
  const float* const s2 = sided ? in.side[dim - 1] : nullptr;
  const float* const sk = sided ? in.skin : nullptr;
  const float si0 = si[0], si1 = si[1], si2 = si[2], ski = si[3];
  // A particle near no thin skin (skin 0) masks nothing: facing >= -1 > -2.
  const float cut_below = ski > 0.0f ? min_facing : -2.0f;
  const double* const x0 = in.x[0];
  const double* const x1 = in.x[1];
  const double* const x2 = in.x[dim - 1];
  const float* const v0 = in.v[0];
  const float* const v1 = in.v[1];
  const float* const v2 = in.v[dim - 1];
  const float* const rho = in.rho;
  const float* const pt = in.pressure_term;
  const float* const vol = in.volume;
  const float inv_h = in.inverse_h, kf = in.kernel_factor;
  const double xi0 = xi[0], xi1 = xi[1], xi2 = xi[2];
  const float vi0 = vi[0], vi1 = vi[1], vi2 = vi[2];
  const float iw = in.inverse_w_dp;
  float a0 = 0, a1 = 0, a2 = 0, ar = 0, aw = 0, vmax = dot_rr2_max;
  float g0 = 0, g1 = 0, g2 = 0, dv = 0, closest = acc_min;
  const std::ptrdiff_t end = je;
#pragma omp simd reduction(+ : a0, a1, a2, ar, aw, g0, g1, g2, dv) reduction(max : vmax)          \
    reduction(min : closest)
  for (std::ptrdiff_t j = jb; j < end; ++j)
  {
    const float dx0 = float(xi0 - x0[j]);
    const float dx1 = float(xi1 - x1[j]);
    const float dx2 = dim == 3 ? float(xi2 - x2[j]) : 0.0f;
    const float r2 = dx0 * dx0 + dx1 * dx1 + dx2 * dx2;
    float t = std::max(0.0f, 1.0f - 0.5f * inv_h * std::sqrt(r2));
    if constexpr (sided)
    {
      const float facing = si0 * s0[j] + si1 * s1[j] + (dim == 3 ? si2 * s2[j] : 0.0f);
      t = (sk[j] == ski && facing < cut_below) ? 0.0f : t; // a select, not a branch
    }
    const float t3 = t * t * t;
    const float fac = kf * t3;
    if constexpr (count_fill)
      aw += t > 0.0f ? 1.0f : 0.0f; // a select, not a branch
    const float dv0 = vi0 - v0[j];
    const float dv1 = vi1 - v1[j];
    const float dv2 = dim == 3 ? vi2 - v2[j] : 0.0f;
    const float dot = dv0 * dx0 + dv1 * dx1 + dv2 * dx2;
    const float rho_sum = rhoi + rho[j];
    float extra, dot_rr2;
    if constexpr (Viscosity::on_gradient)
    {
      const float inv = 1.0f / ((r2 + visc.eta2) * rho_sum);
      dot_rr2 = dot * rho_sum * inv;
      extra = visc.coefficient * std::min(dot, 0.0f) * inv;
    }
    else
    {
      dot_rr2 = dot / (r2 + visc.eta2);
      extra = 0.0f;
    }
    const float s = mj * fac * (pti + pt[j] + extra);
    // Max over all candidate pairs, in support or not (a masked max stops GCC 12
    // from vectorising; pairs beyond 2h only add |v_ij|/(2h), negligible beside c0/h).
    vmax = std::max(vmax, dot_rr2);
    a0 -= s * dx0;
    a1 -= s * dx1;
    a2 -= s * dx2;
    if constexpr (!Viscosity::on_gradient)
    {
      const float lam = mj * visc.coefficient * fac * r2 / (rho_sum * (r2 + visc.eta2));
      a0 += lam * dv0;
      a1 += lam * dv1;
      a2 += lam * dv2;
    }
    float rate = mj * fac * dot;
    if constexpr (neighbour_is_fluid && Diffusion::enabled)
    {
      float drho = rho[j] - rhoi;
      if constexpr (Diffusion::hydrostatic)
        drho += diff.g_over_c2[0] * dx0 + diff.g_over_c2[1] * dx1 + diff.g_over_c2[2] * dx2;
      rate -= diff.two_delta_h_c0 * drho * fac * vol[j];
    }
    ar += rate;
    if constexpr (shifting)
    {
      const float vf = (neighbour_is_fluid ? vol[j] : in.boundary_volume) * fac; // V_j F_ij
      // Floored: near the support's edge w^4 ~ t^16 would fall into the denormal range,
      // whose arithmetic is many times slower, and a regular lattice (the shifted one) has
      // many pairs there (the diagonal 2 dp, 2 dp lies at 2h in 2D).
      const float w = std::max(t3 * t * (5.0f - 4.0f * t) * iw, 1e-6f);
      const float w2 = w * w;
      const float g = vf * (1.0f + 0.2f * w2 * w2);
      g0 += g * dx0;
      g1 += g * dx1;
      g2 += g * dx2;
      dv -= vf * r2;
      if constexpr (neighbour_is_fluid)
        // Pairs that interact only (not across a thin skin), not the particle itself (the
        // one pair at r = 0: float compares only, an index compare halves the loop's
        // speed). A select, not a branch.
        closest = std::min(closest, (t > 0.0f && r2 > 0.0f) ? r2 : 3.4e38f);
    }
  }
  acc[0] += a0;
  acc[1] += a1;
  acc[2] += a2;
  acc[3] += ar;
  acc[4] += aw;
  acc[5] += g0;
  acc[6] += g1;
  acc[7] += g2;
  acc[8] += dv;
  acc_min = closest;
  dot_rr2_max = vmax;
}

/// Gathers for particles [first, last); call inside a parallel region (orphaned `omp
/// for`). Dynamic chunks: each particle's sums do not depend on which thread computes
/// them, and a thread descheduled on a busy machine does not hold the others up.
template <int dim, bool target_is_fluid, bool count_fill, bool sided, bool shifting,
          class Viscosity, class Diffusion>
float particle_loop(const ForcePassInput<dim>& in, const Viscosity& visc, const Diffusion& diff,
                    std::size_t first, std::size_t last)
{
  float dot_rr2_max = 0; // this thread's maximum
  auto one = [&](std::size_t i)
  {
    if (in.active && !in.active[i])
      return;
    double xi[3] = {in.x[0][i], in.x[1][i], dim == 3 ? in.x[dim - 1][i] : 0.0};
    float vi[3] = {in.v[0][i], in.v[1][i], dim == 3 ? in.v[dim - 1][i] : 0.0f};
    const float rhoi = in.rho[i], pti = in.pressure_term[i];
    float si[4] = {0, 0, 0, 0};
    if constexpr (sided)
    {
      for (int d = 0; d < dim; ++d)
        si[d] = in.side[d][i];
      si[3] = in.skin[i];
    }
    float acc[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    float vmax = 0, closest = 3.4e38f;
    const std::int64_t c = in.cell[i];
    auto rows = [&](auto masked)
    {
      constexpr bool mask = decltype(masked)::value;
      for (int r = 0; r < NeighbourGrid<dim>::n_rows; ++r)
      {
        const std::int64_t base = c + in.rows[r];
        gather<dim, true, count_fill, mask, shifting>(
            in, visc, diff, in.fluid_start[base], in.fluid_start[base + 3], xi, vi, rhoi, pti, si,
            target_is_fluid ? -0.5f : 0.5f, in.mass_fluid, acc, closest, vmax);
        if constexpr (target_is_fluid)
          gather<dim, false, count_fill, mask, shifting>(
              in, visc, diff, in.boundary_start[base], in.boundary_start[base + 3], xi, vi, rhoi,
              pti, si, 0.5f, in.mass_boundary, acc, closest, vmax);
      }
    };
    // A particle near no thin skin masks nothing: it takes the plain loop (one branch
    // per particle, none per pair).
    if (sided && si[3] > 0.0f)
      rows(std::true_type{});
    else
      rows(std::false_type{});
    for (int d = 0; d < dim; ++d)
      in.a[d][i] = acc[d];
    in.density_rate[i] = acc[3];
    if constexpr (count_fill)
      in.fill[i] = in.fill_factor * acc[4];
    if constexpr (shifting)
    {
      const std::size_t k = i - first;
      for (int d = 0; d < dim; ++d)
        in.shift_sum[d][k] = acc[5 + d];
      in.position_divergence[k] = acc[8];
      in.closest[k] = closest;
    }
    dot_rr2_max = std::max(dot_rr2_max, vmax);
  };
  // Boundary results are not read by the fluid loop: no barrier between the two.
  if constexpr (target_is_fluid)
  {
#pragma omp for schedule(dynamic, 256)
    for (std::size_t i = first; i < last; ++i)
      one(i);
  }
  else
  {
#pragma omp for schedule(dynamic, 256) nowait
    for (std::size_t i = first; i < last; ++i)
      one(i);
  }
  return dot_rr2_max;
}
} // namespace detail

/// One force pass in ONE parallel region (one barrier per pass matters on a busy
/// machine): boundary particles [0, n_boundary) get their density rates and the fluid's
/// reaction per unit mass (no density diffusion, as in DualSPHysics); fluid particles
/// [n_boundary, n) their accelerations (without gravity and walls) and density rates.
/// Returns max v_ij.r_ij/(r^2+eta2) over candidate pairs, for the time step.
template <int dim, bool count_fill, bool sided, bool shifting, class Viscosity, class Diffusion>
float force_pass(const ForcePassInput<dim>& in, const Viscosity& visc, const Diffusion& diff,
                 std::size_t n_boundary, std::size_t n)
{
  float dot_rr2_max = 0;
#pragma omp parallel if (n > parallel_threshold)
  {
    detail::particle_loop<dim, false, false, sided, false>(in, visc, NoDensityDiffusion{}, 0,
                                                           n_boundary);
    const float m = detail::particle_loop<dim, true, count_fill, sided, shifting>(in, visc, diff,
                                                                                  n_boundary, n);
#pragma omp critical(chipflex_sph_force_pass_max)
    dot_rr2_max = std::max(dot_rr2_max, m); // a maximum: order-independent
  }
  return dot_rr2_max;
}
} // namespace chipflex::sph
