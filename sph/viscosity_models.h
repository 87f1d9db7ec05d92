#pragma once
// Viscosity policies for the force loop (chosen once per run, compiled into the loop).
// Each gives, for one pair i-j, an extra term on the kernel gradient (like a pressure)
// and/or on the relative velocity. eta2 = (0.1 h)^2 keeps r -> 0 finite.

#include <algorithm>

namespace chipflex::sph
{
/// Monaghan (1992): Pi_ij = -alpha c0 mu_ij / rho_avg, mu_ij = h v_ij.r_ij / (r^2 + eta2),
/// active only for approaching pairs (v_ij.r_ij < 0).
struct ArtificialViscosity
{
  static constexpr bool on_gradient = true;
  float two_alpha_c0_h; ///< 2 alpha c0 h (the 2 turns rho_i + rho_j into the mean)
  float eta2;

  /// Pi_ij (adds to p_i/rho_i^2 + p_j/rho_j^2); `dot_rr2` receives v.r/(r^2+eta2) for
  /// the time step limit. One division per pair.
  float gradient_term(float dot, float r2, float rho_sum, float& dot_rr2) const
  {
    const float inv = 1.0f / ((r2 + eta2) * rho_sum);
    dot_rr2 = dot * rho_sum * inv;
    return -two_alpha_c0_h * std::min(dot, 0.0f) * inv;
  }
  float velocity_term(float, float, float) const { return 0; }
};

/// Lo & Shao (2002) laminar viscosity: a_i += sum m_j 4 nu r.grad W / ((rho_i + rho_j)
/// (r^2 + eta2)) v_ij. Conserves linear momentum like the pressure term.
struct LaminarViscosity
{
  static constexpr bool on_gradient = false;
  float four_nu;
  float eta2;

  float gradient_term(float dot, float r2, float, float& dot_rr2) const
  {
    dot_rr2 = dot / (r2 + eta2);
    return 0;
  }
  /// Coefficient on v_ij (per unit neighbour mass); fac = (dW/dr)/r < 0.
  float velocity_term(float fac, float r2, float rho_sum) const
  {
    return four_nu * fac * r2 / (rho_sum * (r2 + eta2));
  }
};
} // namespace chipflex::sph
