// The flow-rate gauge (sph/probes.h): a uniform stream U through a section of wetted
// length L gives Q = (U . n) L; the slab of two spacings holds exactly two lattice columns
// whatever its offset, so the figure is exact up to rounding.

#include "sph/fluid_solver.h"
#include "sph/probes.h"
#include "sph_test_cases.h"

#include <catch2/catch.hpp>

using namespace chipflex::sph;

TEST_CASE("flow-rate gauge: a uniform stream gives U . n times the wetted length", "[sph]")
{
  auto c = testing::closed_box(0.01); // fluid 0.3 x 0.2 m at rest density, no gravity
  c.initial_velocity = Eigen::Vector2d(0.7, -0.2);
  const auto fluid = build_fluid(c);
  fluid->initialise(); // the particles are laid out on the first step otherwise
  // Vertical section, upwards: n = (1, 0); wet over the block's 0.2 m, dry above.
  CHECK(sample_flow_rate(*fluid, {0.1505, 0.0}, {0.1505, 0.35}) == Approx(0.7 * 0.2).epsilon(1e-5));
  // The same section downwards counts the other way.
  CHECK(sample_flow_rate(*fluid, {0.1505, 0.35}, {0.1505, 0.0}) ==
        Approx(-0.7 * 0.2).epsilon(1e-5));
  // Horizontal, along +x: n = (0, -1), so Q = 0.2 m/s * 0.2 m.
  CHECK(sample_flow_rate(*fluid, {0.05, 0.1032}, {0.25, 0.1032}) ==
        Approx(0.2 * 0.2).epsilon(1e-5));
  // Outside the fluid: nothing.
  CHECK(sample_flow_rate(*fluid, {0.35, 0.0}, {0.35, 0.3}) == 0.0);
}

TEST_CASE("3D flow-rate gauge: a uniform stream gives U . n times the wetted area", "[sph]")
{
  CaseDescription<3> c;
  c.fluid.particle_spacing = 0.01;
  c.fluid.gravity = Eigen::Vector3d::Zero();
  c.fluid.speed_of_sound = 20;
  c.fluid.scheme = TimeScheme::symplectic;
  c.fluid_blocks.push_back({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.2, 0.1, 0.1)});
  c.tank.min = Eigen::Vector3d(0, 0, 0);
  c.tank.max = Eigen::Vector3d(0.3, 0.2, 0.2);
  c.tank.open_top = false;
  c.tank.model = WallModel::lennard_jones;
  c.hydrostatic_start = false;
  c.initial_velocity = Eigen::Vector3d(0.7, -0.2, 0.3);
  const auto fluid = build_fluid(c);
  fluid->initialise();
  // The plane x = 0.1005 cuts the block's 0.1 x 0.1 m section: Q = 0.7 * 0.01 m^3/s.
  CHECK(sample_flow_rate(*fluid, {0.1005, 0.5, -3.0}, {1.0, 0.0, 0.0}) ==
        Approx(0.7 * 0.01).epsilon(1e-5));
  // The other way round counts negative; a plane along z takes w over 0.2 x 0.1 m.
  CHECK(sample_flow_rate(*fluid, {0.1005, 0.0, 0.0}, {-1.0, 0.0, 0.0}) ==
        Approx(-0.7 * 0.01).epsilon(1e-5));
  CHECK(sample_flow_rate(*fluid, {0.0, 0.0, 0.0532}, {0.0, 0.0, 1.0}) ==
        Approx(0.3 * 0.02).epsilon(1e-5));
  // Outside the fluid: nothing.
  CHECK(sample_flow_rate(*fluid, {0.25, 0.0, 0.0}, {1.0, 0.0, 0.0}) == 0.0);
}
