#pragma once
// Viscosity policies for the force loop (chosen once per run, compiled into the loop;
// the pair formulas are written out in force_loop.h so that the loop vectorises).
// eta2 = (0.1 h)^2 keeps r -> 0 finite.

namespace chipflex::sph
{
/// Monaghan (1992): Pi_ij = -alpha c0 mu_ij / rho_avg, mu_ij = h v_ij.r_ij / (r^2 + eta2),
/// only for approaching pairs (v_ij.r_ij < 0); Pi_ij adds to p_i/rho_i^2 + p_j/rho_j^2:
///   Pi_ij = coefficient * min(v.r, 0) / ((r^2 + eta2)(rho_i + rho_j)).
struct ArtificialViscosity
{
  static constexpr bool on_gradient = true;
  float coefficient; ///< -2 alpha c0 h (the 2 turns rho_i + rho_j into the mean)
  float eta2;
};

/// Lo & Shao (2002) laminar viscosity:
///   a_i += sum_j m_j 4 nu (r.grad W) / ((rho_i + rho_j)(r^2 + eta2)) v_ij,
/// with r.grad W = F r^2; conserves linear momentum like the pressure term.
struct LaminarViscosity
{
  static constexpr bool on_gradient = false;
  float coefficient; ///< 4 nu
  float eta2;
};
} // namespace chipflex::sph
