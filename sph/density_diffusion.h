#pragma once
// Density diffusion (delta-SPH) policies for the continuity equation, fluid-fluid pairs:
//   D_i += 2 delta h c0 sum_j (rho_j - rho_i - rho^H_ji) (r_ji . grad_i W) / r^2 V_j.
// With grad_i W = F r_ij, (r_ji . grad_i W)/r^2 = -F, so no division is needed.
//
// Molteni & Colagrossi (2009): rho^H = 0. It diffuses the hydrostatic density gradient
// too, which lets a resting column sag near the bottom.
// Fourtakas et al. (2019): rho^H_ji = rho0 ((1 + rho0 g.(x_j-x_i)/B)^(1/gamma) - 1),
// the hydrostatic part, so only the dynamic density is diffused. Over one kernel
// support the argument is ~ gamma g 2h / c0^2 < 1e-3, so the power is replaced by its
// first-order term rho0 g.(x_j - x_i) / c0^2 (the next term is below float resolution).

namespace chipflex::sph
{
struct NoDensityDiffusion
{
  static constexpr bool enabled = false;
  static constexpr bool hydrostatic = false;
  float two_delta_h_c0 = 0;
  float g_over_c2[3] = {0, 0, 0};
};

struct MolteniColagrossiDiffusion
{
  static constexpr bool enabled = true;
  static constexpr bool hydrostatic = false;
  float two_delta_h_c0;
  float g_over_c2[3] = {0, 0, 0};
};

struct FourtakasDiffusion
{
  static constexpr bool enabled = true;
  static constexpr bool hydrostatic = true;
  float two_delta_h_c0;
  float g_over_c2[3]; ///< rho0 g / c0^2 per component
};
} // namespace chipflex::sph
