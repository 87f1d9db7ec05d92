#pragma once
// Tait's equation of state p = B ((rho/rho0)^gamma - 1), B = rho0 c0^2 / gamma: a stiff
// barotropic law that keeps density variations near 1 % when c0 is ten times the
// largest flow speed (weakly compressible SPH).

#include <cmath>

namespace chipflex::sph
{
struct TaitEquationOfState
{
  TaitEquationOfState(double rho0, double c0, double gamma)
      : rho0(rho0), c0(c0), gamma(gamma), B(rho0 * c0 * c0 / gamma), inverse_rho0(1.0 / rho0),
        integer_gamma_7(gamma == 7)
  {
  }

  /// Pressure, Pa. gamma = 7 (water) by multiplications: the pressure is evaluated for
  /// every particle every force pass.
  float pressure(float rho) const
  {
    const float x = rho * float(inverse_rho0);
    if (integer_gamma_7)
    {
      const float x2 = x * x, x4 = x2 * x2;
      return float(B) * (x4 * x2 * x - 1.0f);
    }
    return float(B * (std::pow(double(x), gamma) - 1.0));
  }
  double pressure(double rho) const { return B * (std::pow(rho / rho0, gamma) - 1.0); }
  /// Inverse: the density that gives pressure p (hydrostatic initial state).
  double density(double p) const { return rho0 * std::pow(1.0 + p / B, 1.0 / gamma); }

  double rho0, c0, gamma, B, inverse_rho0;
  bool integer_gamma_7;
};
} // namespace chipflex::sph
