// Restart and thread-count independence: a run continued from a checkpoint ends
// bitwise equal to the uninterrupted run, and 1 and 2 threads give bitwise equal
// results (per-particle gathers in a fixed neighbour order, sequential sorting).

#include "common/hdf5_file.h"
#include "sph/fluid_solver.h"
#include "sph_test_cases.h"

#include <catch2/catch.hpp>
#include <cstdio>
#include <omp.h>

using namespace chipflex::sph;

namespace
{
void require_identical(const FluidSolver<2>& a, const FluidSolver<2>& b)
{
  REQUIRE(a.n_particles() == b.n_particles());
  REQUIRE(a.time() == b.time());
  REQUIRE(a.step_count() == b.step_count());
  const auto& p = a.particles();
  const auto& q = b.particles();
  std::size_t differences = 0;
  for (std::size_t i = 0; i < a.n_particles(); ++i)
  {
    bool same = p.id[i] == q.id[i] && p.density[i] == q.density[i];
    for (int d = 0; d < 2; ++d)
      same = same && p.position[d][i] == q.position[d][i] && p.velocity[d][i] == q.velocity[d][i];
    differences += !same;
  }
  CHECK(differences == 0);
}

CaseDescription<2> sloshing_case(TimeScheme scheme)
{
  auto c = testing::water_column(0.3, 0.2, 0.01);
  c.tank.max = Eigen::Vector2d(0.6, 0.4);
  c.fluid.scheme = scheme;
  c.fluid.verlet_euler_every = 7; // exercise the Euler step across the restart
  return c;
}
} // namespace

TEST_CASE("restart from a checkpoint repeats the uninterrupted run bitwise", "[sph][restart]")
{
  for (const auto scheme :
       {TimeScheme::verlet, TimeScheme::symplectic, TimeScheme::position_verlet})
  {
    DYNAMIC_SECTION("scheme " << int(scheme))
    {
      auto c1 = sloshing_case(scheme);
      auto whole = build_fluid(c1);
      const std::string path = "sph_restart_test_" + std::to_string(int(scheme)) + ".h5";
      for (int s = 0; s < 60; ++s)
        whole->step();
      {
        chipflex::Hdf5File h5(path, chipflex::Hdf5File::Mode::create);
        whole->save(h5, "/fluid");
      }
      for (int s = 0; s < 60; ++s)
        whole->step();

      auto c2 = sloshing_case(scheme);
      auto resumed = build_fluid(c2);
      {
        const chipflex::Hdf5File h5(path, chipflex::Hdf5File::Mode::read);
        resumed->load(h5, "/fluid");
      }
      REQUIRE(resumed->step_count() == 60);
      for (int s = 0; s < 60; ++s)
        resumed->step();
      require_identical(*whole, *resumed);
      std::remove(path.c_str());
    }
  }
}

TEST_CASE("results do not depend on the thread count", "[sph][threads]")
{
  const int threads = omp_get_max_threads();
  auto run = [](int n)
  {
    omp_set_num_threads(n);
    // Enough particles for the parallel loops (sph::parallel_threshold), and a
    // Lennard-Jones floor strip so that the wall path runs threaded too.
    auto c = testing::water_column(0.3, 0.2, 0.005);
    c.tank.max = Eigen::Vector2d(0.6, 0.4);
    WallSurface<2> strip;
    strip.name = "strip";
    strip.vertices = {Eigen::Vector2d(0.25, 0), Eigen::Vector2d(0.05, 0)};
    strip.faces = {{0, 1}};
    c.walls.push_back(strip);
    auto f = build_fluid(c);
    for (int s = 0; s < 80; ++s)
      f->step();
    return f;
  };
  auto one = run(1);
  auto two = run(2);
  omp_set_num_threads(threads);
  require_identical(*one, *two);
}
