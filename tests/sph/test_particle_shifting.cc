// Particle shifting (sph/particle_shifting.h, delta+-SPH of Sun et al. 2017): the shift
// rule at a free surface, in spray and at its cap, and its effect on a disordered fluid.
#include "sph/case_setup.h"
#include "sph/fluid_solver.h"
#include "sph/particle_shifting.h"
#include "sph_test_cases.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>

using namespace chipflex::sph;

TEST_CASE("the shift follows the concentration gradient inside and stops at a free surface",
          "[sph][shifting]")
{
  double dr[2];
  // Inside (div r = 2): dr = -D sum.
  const float sum[2] = {30.0f, -40.0f};
  particle_shift<2>(sum, 2.0f, 1e-5f, 1.0f, dr);
  CHECK(dr[0] == Approx(-3e-4).epsilon(1e-6));
  CHECK(dr[1] == Approx(4e-4).epsilon(1e-6));
  // The cap: |dr| = 5e-4 limited to 1e-4, the direction kept.
  particle_shift<2>(sum, 2.0f, 1e-5f, 1e-4f, dr);
  CHECK(std::hypot(dr[0], dr[1]) == Approx(1e-4).epsilon(1e-6));
  CHECK(dr[0] / dr[1] == Approx(-0.75).epsilon(1e-6));
  // A free surface (div r = 1.2 < 1.5) or spray: no shift (the gradient points into the
  // fluid and would carry the surface outwards).
  for (float divergence : {1.2f, 0.4f})
  {
    particle_shift<2>(sum, divergence, 1e-5f, 1.0f, dr);
    CHECK(dr[0] == 0.0);
    CHECK(dr[1] == 0.0);
  }
  // 3D: the threshold at 2.5.
  double dr3[3];
  const float sum3[3] = {0.0f, 0.0f, -10.0f};
  particle_shift<3>(sum3, 2.0f, 1e-5f, 1.0f, dr3);
  CHECK(std::abs(dr3[2]) < 1e-15);
  particle_shift<3>(sum3, 2.9f, 1e-5f, 1.0f, dr3);
  CHECK(dr3[2] == Approx(1e-4).epsilon(1e-6));
}

namespace
{
/// Smallest distance between two fluid particles (all pairs).
double closest_pair(const FluidSolver<2>& fluid)
{
  double best = 1e300;
  for (std::size_t i = fluid.n_boundary(); i < fluid.n_particles(); ++i)
    for (std::size_t j = i + 1; j < fluid.n_particles(); ++j)
      best = std::min(best, (fluid.position(i) - fluid.position(j)).norm());
  return best;
}

/// A closed, weightless box full of water whose particles sit up to 0.3 dp off their
/// lattice (a fixed pseudo-random pattern), turning in one cell vortex of 0.1 m/s (the
/// shift grows with a particle's speed; the vortex's velocity is along the walls, so the
/// fluid keeps moving without running into them), for 0.1 s.
struct DisorderedBox
{
  double start_closest = 0, end_closest = 0, reported = 0;
  std::size_t lost = 0;
};

DisorderedBox run_disordered_box(double shifting)
{
  const double dp = 0.01, L = 0.2;
  FluidParameters<2> f;
  f.particle_spacing = dp;
  f.gravity = Eigen::Vector2d::Zero();
  f.speed_of_sound = 20;
  f.shifting_coefficient = shifting;
  // The jittered start at uniform density stretches the fluid in places: keep the run
  // going (this test is about spacing, not about tension).
  f.minimum_density_ratio = 0.3;
  f.maximum_lost_fraction = 1;
  f.domain_min = Eigen::Vector2d::Constant(-0.1);
  f.domain_max = Eigen::Vector2d::Constant(L + 0.1);
  auto fluid = std::make_unique<FluidSolver<2>>(f);
  TankDescription<2> tank;
  tank.min = Eigen::Vector2d(0, 0);
  tank.max = Eigen::Vector2d(L, L);
  tank.open_top = false;
  fluid->add_wall(tank_walls(tank));
  std::vector<Eigen::Vector2d> x;
  std::uint32_t seed = 12345;
  auto jitter = [&]
  {
    seed = seed * 1664525u + 1013904223u;
    return 0.6 * (double(seed >> 8) / double(1u << 24) - 0.5); // [-0.3, 0.3)
  };
  const int n = int(std::lround(L / dp));
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
    {
      const double ja = jitter(), jb = jitter();
      x.emplace_back((a + 0.5 + ja) * dp, (b + 0.5 + jb) * dp);
    }
  std::vector<Eigen::Vector2d> v;
  for (const auto& xi : x)
    v.emplace_back(0.1 * std::sin(M_PI * xi[0] / L) * std::cos(M_PI * xi[1] / L),
                   -0.1 * std::cos(M_PI * xi[0] / L) * std::sin(M_PI * xi[1] / L));
  fluid->add_fluid_particles(x, {}, v);
  fluid->initialise();
  DisorderedBox r;
  r.start_closest = closest_pair(*fluid) / dp;
  while (fluid->time() < 0.1)
    fluid->step();
  r.lost = fluid->lost_particles().size();
  r.end_closest = closest_pair(*fluid) / dp;
  r.reported = fluid->closest_fluid_pair().distance / dp;
  return r;
}
} // namespace

TEST_CASE("particle shifting spreads a disordered fluid towards a lattice", "[sph][shifting]")
{
  const auto plain = run_disordered_box(0);
  const auto shifted = run_disordered_box(2);
  std::cout << "disordered box, closest pair / dp: start " << plain.start_closest
            << "; after 0.1 s without shifting " << plain.end_closest << ", with "
            << shifted.end_closest << " (the solver's record " << shifted.reported << "); "
            << plain.lost << " and " << shifted.lost << " particles lost\n";
  // The jitter puts some pairs far closer than dp; the pressure alone (every particle
  // starts at rho0) leaves them close, the shift's concentration gradient and its
  // tensile term push them apart.
  CHECK(plain.start_closest < 0.5);
  CHECK(shifted.lost == 0);
  CHECK(shifted.end_closest > 0.75);
  CHECK(shifted.end_closest > plain.end_closest + 0.05);
  // The solver's record of the closest pair: its first pass saw the starting lattice.
  CHECK(shifted.reported == Approx(shifted.start_closest).epsilon(1e-4));
  // Without shifting nothing measures it.
  CHECK(std::isinf(plain.reported));
}
