// Clamped and free-free frequencies against beam theory, and convergence under refinement.
#include "fem_test_support.h"

#include <catch2/catch.hpp>

using namespace chipflex::fem;
using namespace chipflex::fem::testing;

TEST_CASE("clamped 2D gate: first bending frequencies against Euler-Bernoulli", "[fem]")
{
  // Antoci gate, plane strain: bending stiffness per metre E/(1-nu^2) t^3/12. The default
  // mesh (t/4) with quadratic quads. Timoshenko's shear correction for mode 1 at L/t = 15.8
  // is about -0.25 %; 1 % bounds it with the 2D clamp's local stiffening.
  ReductionSettings s;
  s.material = {1.2e7, 0.4, 1100, false}; // the gate's rubber
  s.mesh_file = gate_mesh(0.005 / 4);
  s.clamp_group = "clamp";
  s.n_modes = 3;
  const auto body = reduce_body(s);
  const double e = s.material.youngs_modulus / (1 - std::pow(s.material.poisson_ratio, 2));
  const double t = 0.005, l = 0.079;
  const double f1 = cantilever_frequency(0, e, t * t * t / 12, s.material.density, t, l);
  INFO("f1 FE " << body.frequencies_hz[0] << " Hz, Euler-Bernoulli " << f1 << " Hz");
  CHECK(body.frequencies_hz[0] == Approx(f1).epsilon(0.01));
  // Mode 2 carries more shear (Timoshenko: -1.5 % at this slenderness): within 3 %, and below
  // the Euler-Bernoulli value, as shear deformation must make it.
  const double f2 = cantilever_frequency(1, e, t * t * t / 12, s.material.density, t, l);
  INFO("f2 FE " << body.frequencies_hz[1] << " Hz, Euler-Bernoulli " << f2 << " Hz");
  CHECK(body.frequencies_hz[1] == Approx(f2).epsilon(0.03));
  CHECK(body.frequencies_hz[1] < f2);
  for (const auto& kind : body.mode_kinds)
    CHECK(kind == "normal");
}

TEST_CASE("clamped 3D strip: bending frequencies in both planes against Euler-Bernoulli", "[fem]")
{
  // Steel-like strip 100 x 4 x 2 mm, quadratic hexahedra of 1 mm. Bending about the thin
  // axis (I = w t^3/12) and about the wide axis (I = t w^3/12): ratio w/t = 2.
  ReductionSettings s;
  s.material = {2.1e11, 0.3, 7850, false};
  const double l = 0.1, w = 0.004, t = 0.002;
  s.mesh_file = strip_mesh(l, w, t, 0.001);
  s.clamp_group = "clamp";
  s.n_modes = 2;
  const auto body = reduce_body(s);
  const double e = s.material.youngs_modulus, rho = s.material.density;
  const double thin = cantilever_frequency(0, e, w * t * t * t / 12, rho, w * t, l);
  const double wide = cantilever_frequency(0, e, t * w * w * w / 12, rho, w * t, l);
  INFO("FE " << body.frequencies_hz[0] << ", " << body.frequencies_hz[1] << " Hz; EB " << thin
             << ", " << wide << " Hz");
  CHECK(body.frequencies_hz[0] == Approx(thin).epsilon(0.01));
  CHECK(body.frequencies_hz[1] == Approx(wide).epsilon(0.01));
}

TEST_CASE("free-free 2D gate: no rigid modes, elastic frequencies converge", "[fem]")
{
  // Free-free beam theory: f1 = 4.730^2 / (2 pi L^2) sqrt(E I / rho A).
  const double t = 0.005, l = 0.079;
  std::vector<double> f1;
  for (const double size : {t / 1, t / 2, t / 4})
  {
    ReductionSettings s;
    s.material = {1.2e7, 0.4, 1100, false}; // the gate's rubber
    s.mesh_file = gate_mesh(size);
    s.n_modes = 4;
    const auto body = reduce_body(s);
    REQUIRE(body.n_modes() == 4);
    // A rigid mode would have f ~ 0; the lowest must be the first bending mode.
    const double e = s.material.youngs_modulus / (1 - std::pow(s.material.poisson_ratio, 2));
    const double reference = free_free_frequency(0, e, t * t * t / 12, s.material.density, t, l);
    CHECK(body.frequencies_hz[0] > 0.9 * reference);
    CHECK(body.frequencies_hz[0] < 1.02 * reference);
    for (int k = 1; k < 4; ++k)
      CHECK(body.frequencies_hz[k] >= body.frequencies_hz[k - 1] * (1 - 1e-9));
    // Modes carry no rigid motion: no net momentum, sum_ij Ms_ij psi_j = 0.
    CHECK(body.translation_coupling.norm() < 1e-9 * std::sqrt(body.mass));
    f1.push_back(body.frequencies_hz[0]);
  }
  // Stiffness-based FE converges from above, and the differences shrink.
  CHECK(f1[0] >= f1[1]);
  CHECK(f1[1] >= f1[2]);
  CHECK(std::abs(f1[2] - f1[1]) < 0.25 * std::abs(f1[1] - f1[0]));
}

TEST_CASE("free-free 3D plate on quadratic tetrahedra: no rigid modes, converges", "[fem]")
{
  std::vector<double> f;
  for (const double size : {0.004, 0.002})
  {
    ReductionSettings s;
    s.material = {2.1e11, 0.3, 7850, false};
    s.mesh_file = strip_mesh(0.08, 0.006, 0.004, size, true);
    s.n_modes = 3;
    const auto body = reduce_body(s);
    CHECK(body.frequencies_hz[0] > 100); // rigid modes would be ~0 Hz
    CHECK(body.translation_coupling.norm() < 1e-9 * std::sqrt(body.mass));
    f.push_back(body.frequencies_hz[0]);
  }
  // First bending about the thin axis; Euler-Bernoulli within 2 % (at L/t = 20 Timoshenko's
  // shear correction lowers it by about 1 %).
  const double e = 2.1e11, t = 0.004, w = 0.006, l = 0.08;
  const double reference = free_free_frequency(0, e, w * t * t * t / 12, 7850, w * t, l);
  INFO("f1 " << f[0] << " -> " << f[1] << " Hz, beam " << reference);
  CHECK(f[1] <= f[0]);
  CHECK(std::abs(f[1] - f[0]) < 0.01 * f[1]);
  CHECK(f[1] == Approx(reference).epsilon(0.02));
  CHECK(f[1] < reference);
}
