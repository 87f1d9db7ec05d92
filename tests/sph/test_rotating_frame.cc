// The fluid in a turning frame (sph: centrifugal, Coriolis and Euler accelerations).
// 1. Lone fluid particles (beyond each other's kernel) at rest in the lab, seen from a
//    frame that spins up and then turns steadily: each follows its lab position turned
//    back by the frame's angle, x(t) = Rf(t)^T (x0 - o) + o (an exact path).
// 2. A closed tank of water turning with the frame (the forced vortex, at rest in the
//    frame): the pressure rises from the axis as rho Omega^2 r^2 / 2, the centrifugal
//    counterpart of the hydrostatic tank.

#include "sph/fluid_solver.h"
#include "sph/probes.h"
#include "sph_test_cases.h"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <iostream>

using namespace chipflex;
using namespace chipflex::sph;

namespace
{
template <int dim>
double lone_particle_path_error(const RotatingFrame& frame)
{
  using V = Eigen::Matrix<double, dim, 1>;
  FluidParameters<dim> p;
  p.particle_spacing = 0.01;
  p.gravity = V::Zero();
  p.speed_of_sound = 20;
  p.scheme = TimeScheme::symplectic;
  p.domain_min = V::Constant(-1);
  p.domain_max = V::Constant(1);
  p.rotating_frame = frame;
  FluidSolver<dim> fluid(p);
  std::vector<V> x0;
  for (int k = 0; k < 5; ++k) // 0.1 m apart: no neighbours (2h = 0.028 m in 2D)
  {
    V x = V::Zero();
    x[0] = 0.05 + 0.1 * k;
    x[1] = -0.1 + 0.05 * k;
    if constexpr (dim == 3)
      x[2] = 0.02 * k;
    x0.push_back(x);
  }
  fluid.add_fluid_particles(x0);
  fluid.initialise();
  const V o = frame.axis_point.template head<dim>();
  double error = 0;
  while (fluid.time() < 0.6)
  {
    fluid.step();
    Eigen::Matrix<double, dim, dim> rf;
    const double angle = frame.angle(fluid.time());
    if constexpr (dim == 2)
      rf = Eigen::Rotation2Dd(frame.angular_velocity.z() > 0 ? angle : -angle).toRotationMatrix();
    else
      rf = Eigen::AngleAxisd(angle, frame.angular_velocity.normalized()).toRotationMatrix();
    REQUIRE(fluid.n_particles() == fluid.n_boundary() + x0.size());
    for (std::size_t i = fluid.n_boundary(); i < fluid.n_particles(); ++i)
    {
      // match by the nearest expected position: the solver may reorder its particles
      double best = 1e300;
      for (const V& x : x0)
        best = std::min(best, (fluid.position(i) - (rf.transpose() * (x - o) + o)).norm());
      error = std::max(error, best);
    }
  }
  return error;
}
} // namespace

TEST_CASE("lone fluid particles in a turning frame follow their lab rest turned back",
          "[sph][rotating_frame][heavy]")
{
  RotatingFrame frame;
  frame.axis_point = Eigen::Vector3d(0.02, -0.03, 0);
  frame.spin_up_time = 0.2;
  frame.angular_velocity = Eigen::Vector3d(0, 0, 20); // 10.0 rad turned by 0.6 s
  const double e2 = lone_particle_path_error<2>(frame);
  frame.angular_velocity = Eigen::Vector3d(6, -8, 16);
  const double e3 = lone_particle_path_error<3>(frame);
  // Radii up to 0.45 m; the step (CFL on c0 = 20 m/s) turns the frame by ~3e-3 rad, and
  // the second-order error over 10 rad is (Omega dt)^2 theta r ~ 4e-5 m (measured: 4.2e-5
  // and 5.3e-5 m). Evaluating the mid-step pass at the step's start instead gave 6e-4 m;
  // a missing term (without Coriolis the points fly outwards) fails by far.
  std::cout << "lone particles in a turning frame: largest path error " << e2 << " m (2D), " << e3
            << " m (3D)\n";
  CHECK(e2 < 1e-4);
  CHECK(e3 < 1e-4);
}

TEST_CASE("water turning with its closed tank: p - p(axis) = rho Omega^2 r^2 / 2",
          "[sph][rotating_frame][heavy]")
{
  // A square tank 0.24 m wide around the axis, full, dummy-particle walls, at rest in a
  // frame turning at 20 rad/s from the start (the lab's rigid rotation, an exact steady
  // state). The fluid starts at rho0 and settles acoustically; the pressure is averaged
  // over the last 0.4 s of 1.2 s.
  const double dp = 0.01, half = 0.12, omega = 20, rho0 = 1000;
  auto c = testing::water_column(2 * half, 2 * half, dp);
  c.fluid_blocks[0] = {Eigen::Vector2d(-half, -half), Eigen::Vector2d(half, half)};
  c.tank.min = Eigen::Vector2d(-half, -half);
  c.tank.max = Eigen::Vector2d(half, half);
  c.tank.open_top = false;
  c.fluid.gravity = Eigen::Vector2d::Zero();
  c.fluid.speed_of_sound = 20; // rho0 c0^2 = 4e5 Pa, 100 x the largest pressure
  c.hydrostatic_start = false;
  c.fluid.rotating_frame.angular_velocity = Eigen::Vector3d(0, 0, omega);
  auto fluid = build_fluid(c);
  fluid->initialise();
  const std::size_t n0 = fluid->n_particles();
  const std::vector<Eigen::Vector2d> points = {{0, 0},     {0.04, 0},        {0.08, 0},
                                               {0, -0.08}, {0.0566, 0.0566}, {-0.0566, -0.0566}};
  std::vector<double> sum(points.size(), 0.0);
  int samples = 0;
  while (fluid->time() < 1.2)
  {
    fluid->step();
    if (fluid->time() > 0.8 && fluid->step_count() % 10 == 0)
    {
      for (std::size_t k = 0; k < points.size(); ++k)
        sum[k] += sample_pressure(*fluid, points[k]);
      ++samples;
    }
  }
  CHECK(fluid->n_particles() == n0);
  const double p_axis = sum[0] / samples;
  for (std::size_t k = 1; k < points.size(); ++k)
  {
    const double r = points[k].norm(), p = sum[k] / samples - p_axis;
    const double expected = 0.5 * rho0 * omega * omega * r * r;
    std::cout << "forced vortex: r = " << r << " m, p - p(axis) = " << p
              << " Pa, rho Omega^2 r^2 / 2 = " << expected << " Pa\n";
    // 5 % of the value at r = 0.08 m (1280 Pa): the hydrostatic tank's accuracy
    CHECK(std::abs(p - expected) < 0.05 * 1280);
  }
}
