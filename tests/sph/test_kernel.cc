// Wendland C2 kernel: normalisation (integral of W = 1, analytic property of the kernel),
// the discrete partition of unity and gradient consistency on a lattice
// (sum_j V_j (x_j - x_i) grad_i W_ij = I for a full support), and the gradient against
// a finite difference of W.

#include "sph/wendland_kernel.h"

#include <catch2/catch.hpp>

using chipflex::sph::WendlandKernel;

TEST_CASE("Wendland kernel integrates to one (2D and 3D)", "[sph][kernel]")
{
  const double h = 0.013;
  const WendlandKernel<2> w2(h);
  const WendlandKernel<3> w3(h);
  // Radial quadrature: int W dA = int 2 pi r W dr, int W dV = int 4 pi r^2 W dr.
  double s2 = 0, s3 = 0;
  const int n = 20000;
  const double dr = 2 * h / n;
  for (int k = 0; k < n; ++k)
  {
    const double r = (k + 0.5) * dr;
    s2 += 2 * M_PI * r * w2.value(r) * dr;
    s3 += 4 * M_PI * r * r * w3.value(r) * dr;
  }
  CHECK(s2 == Approx(1).epsilon(1e-6));
  CHECK(s3 == Approx(1).epsilon(1e-6));
  CHECK(w2.value(2 * h) == 0);
  CHECK(w2.value(2.5 * h) == 0);
}

TEST_CASE("Wendland gradient equals the derivative of W", "[sph][kernel]")
{
  const double h = 0.02;
  const WendlandKernel<2> w(h);
  for (double q : {0.1, 0.5, 1.0, 1.5, 1.9})
  {
    const double r = q * h, e = 1e-7 * h;
    const double derivative = (w.value(r + e) - w.value(r - e)) / (2 * e);
    CHECK(w.gradient_over_r(r) * r == Approx(derivative).epsilon(1e-6));
  }
}

TEST_CASE("lattice sums: partition of unity and gradient consistency", "[sph][kernel]")
{
  const double dp = 0.01, h = std::sqrt(2.0) * dp;
  const WendlandKernel<2> w(h);
  double sum = 0, m[2][2] = {{0, 0}, {0, 0}};
  for (int i = -5; i <= 5; ++i)
    for (int j = -5; j <= 5; ++j)
    {
      const double x = i * dp, y = j * dp, r = std::hypot(x, y);
      sum += dp * dp * w.value(r);
      // x_j - x_i = (x, y); grad_i W = F(r) (x_i - x_j) = -F (x, y)
      const double f = -w.gradient_over_r(r);
      m[0][0] += dp * dp * x * f * x;
      m[0][1] += dp * dp * x * f * y;
      m[1][1] += dp * dp * y * f * y;
    }
  CHECK(sum == Approx(1).epsilon(0.01));
  CHECK(m[0][0] == Approx(1).epsilon(0.01));
  CHECK(m[1][1] == Approx(1).epsilon(0.01));
  CHECK(std::abs(m[0][1]) < 1e-12);
}
