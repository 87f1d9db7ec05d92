#pragma once
// The Wendland C2 kernel (Wendland 1995), support radius 2h:
//   W(q) = alpha_d (1 - q/2)^4 (2q + 1),  q = r/h <= 2,
//   alpha_2 = 7 / (4 pi h^2),  alpha_3 = 21 / (16 pi h^3).
// It is positive definite (no pairing instability) and cheap: the force loop only needs
//   grad_i W = F(r) r_ij,  F(r) = (dW/dr)/r = -5 alpha_d (1 - q/2)^3 / h^2,
// so no square root is wasted on a direction vector.

#include <cmath>

namespace chipflex::sph
{
template <int dim>
struct WendlandKernel
{
  explicit WendlandKernel(double h)
      : h(h), alpha(dim == 2 ? 7.0 / (4.0 * M_PI * h * h) : 21.0 / (16.0 * M_PI * h * h * h)),
        gradient_factor(-5.0 * alpha / (h * h))
  {
  }

  double value(double r) const
  {
    const double q = r / h;
    if (q >= 2)
      return 0;
    const double t = 1 - 0.5 * q;
    return alpha * t * t * t * t * (2 * q + 1);
  }
  /// F(r) = (dW/dr) / r; grad_i W_ij = F(r) (x_i - x_j).
  double gradient_over_r(double r) const
  {
    const double q = r / h;
    if (q >= 2)
      return 0;
    const double t = 1 - 0.5 * q;
    return gradient_factor * t * t * t;
  }
  double support() const { return 2 * h; }

  double h, alpha, gradient_factor;
};
} // namespace chipflex::sph
