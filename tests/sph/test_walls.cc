// Lennard-Jones wall: the force law of docs/sph.md (F(0) = k, F(r0) = 0, F(R) = 0,
// attractive between r0 and R), its derived defaults, and a settled water column held
// only by Lennard-Jones walls: the wall row rests at about r0, no particle penetrates.

#include "sph/fluid_solver.h"
#include "sph/lennard_jones_wall.h"
#include "sph_test_cases.h"

#include <catch2/catch.hpp>

using namespace chipflex::sph;

TEST_CASE("modified Lennard-Jones force law", "[sph][walls]")
{
  const LennardJonesParameters p{1000, 0.01, 0.005};
  const LennardJonesForce f(p);
  CHECK(f(0) == Approx(1000).epsilon(1e-12));
  CHECK(std::abs(f(0.005)) < 1e-9);
  CHECK(f(0.01) == 0);
  CHECK(f(0.02) == 0);
  CHECK(f(0.0075) < 0);                         // slightly attractive beyond r0
  CHECK(f(0.0025) > 0);                         // repulsive inside r0
  CHECK(f(-0.001) == Approx(1000));             // crossed: pushed back with k
  const double R = 0.01, r0 = 0.005, d = 0.003; // the formula written out
  const double expected = 1000 * (std::pow(R - d, 4) - std::pow(R - r0, 2) * std::pow(R - d, 2)) /
                          (R * R * r0 * (2 * R - r0));
  CHECK(f(d) == Approx(expected).epsilon(1e-12));
}

TEST_CASE("Lennard-Jones defaults from spacing and expected pressure", "[sph][walls]")
{
  const auto p = derive_lennard_jones({}, 0.01, 1000, 2000, "w");
  CHECK(p.r0 == Approx(0.005));
  CHECK(p.R == Approx(0.01));
  CHECK(p.k == Approx(10 * 2000 / (1000 * 0.01)));
  const auto given = derive_lennard_jones({5, 0.02, 0.01}, 0.01, 1000, 2000, "w");
  CHECK(given.k == 5);
  CHECK(given.R == 0.02);
  CHECK_THROWS(derive_lennard_jones({5, 0.01, 0.02}, 0.01, 1000, 2000, "w"));
}

TEST_CASE("a column held by Lennard-Jones walls rests at about r0 and never penetrates",
          "[sph][walls]")
{
  const double width = 0.2, height = 0.2, dp = 0.01;
  auto c = testing::water_column(width, height, dp, WallModel::lennard_jones);
  auto fluid = build_fluid(c);
  const double r0 = fluid->wall(0).lennard_jones.r0;
  REQUIRE(r0 == Approx(dp / 2));
  double closest = 1;
  while (fluid->time() < 1.5)
  {
    fluid->step();
    for (std::size_t i = fluid->n_boundary(); i < fluid->n_particles(); ++i)
    {
      const auto x = fluid->position(i);
      closest = std::min({closest, x[0], width - x[0], x[1]});
    }
  }
  CHECK(closest > 0); // no penetration, ever
  // The bottom row after settling: mean distance from the floor.
  double sum = 0;
  int n = 0;
  for (std::size_t i = fluid->n_boundary(); i < fluid->n_particles(); ++i)
    if (fluid->position(i)[1] < 0.75 * dp + 0.5 * dp)
    {
      sum += fluid->position(i)[1];
      ++n;
    }
  REQUIRE(n >= int(width / dp) - 2);
  const double mean = sum / n;
  INFO("mean bottom-row height " << mean << " m, r0 = " << r0 << " m, closest " << closest);
  CHECK(mean > 0.7 * r0);
  CHECK(mean < 1.3 * r0);
}
