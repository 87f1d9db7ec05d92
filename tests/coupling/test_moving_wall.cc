// Walls with a prescribed motion (coupling/prescribed_motion_body.h).
// 1. Kinematics: the skin is the initial one moved rigidly, x = c + v t + R(omega t)(x0 - c),
//    with velocity v + omega x (x - c(t)) (exact; compared with finite differences).
// 2. Newton's third law: a paddle turning in the water of a closed box without gravity
//    stirs the fluid; the momentum the fluid gains is what the paddle's drive (its
//    impulse) and the box walls give, to the fluid's float round-off.

#include "coupling/co_simulation.h"
#include "coupling/prescribed_motion_body.h"
#include "sph/case_setup.h"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

using namespace chipflex;

TEST_CASE("a moving wall's skin moves rigidly with its prescribed velocity and spin")
{
  using Vector = Eigen::Vector3d;
  coupling::PrescribedMotion<3> motion;
  motion.velocity = Vector(0.1, -0.2, 0.05);
  motion.centre = Vector(1, 2, 3);
  motion.axis = Vector(1, 1, 2); // normalised by the body
  motion.angular_speed = 4;
  const std::vector<Vector> x0 = {{1.5, 2, 3}, {1, 2.5, 3.2}, {0.8, 1.9, 3.7}};
  coupling::PrescribedMotionBody<3> wall(x0, {{0, 1, 2}}, motion);
  const double dt = 1e-6;
  for (int k = 0; k < 100; ++k)
    wall.advance(0.003);
  std::vector<Vector> x, v, x_next;
  wall.skin_positions(x);
  wall.skin_velocities(v);
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(4 * 0.3, Vector(1, 1, 2).normalized()).toRotationMatrix();
  for (int i = 0; i < 3; ++i)
    CHECK((x[i] - (motion.centre + 0.3 * motion.velocity + r * (x0[i] - motion.centre))).norm() <
          1e-12);
  wall.advance(dt);
  wall.skin_positions(x_next);
  for (int i = 0; i < 3; ++i)
    CHECK(((x_next[i] - x[i]) / dt - v[i]).norm() < 1e-5 * v[i].norm());
}

TEST_CASE("a wall turning in place keeps its vertices and moves them at omega x r")
{
  // A cylinder turning about its own axis maps onto itself: `in_place` leaves the
  // vertices where they are and gives them the velocity omega a x (x - c), tangential to
  // the cylinder (a borehole wall past a drill's flute); its torque about the axis is
  // that of its forces.
  using Vector = Eigen::Vector3d;
  coupling::PrescribedMotion<3> motion;
  motion.centre = Vector(0, 0, 0);
  motion.axis = Vector(0, 0, 1);
  motion.angular_speed = -133;
  motion.in_place = true;
  const double radius = 0.01;
  std::vector<Vector> x0;
  for (int k = 0; k < 5; ++k)
    x0.push_back(radius * Vector(std::cos(0.3 * k), std::sin(0.3 * k), 0.002 * k));
  coupling::PrescribedMotionBody<3> wall(x0, {{0, 1, 2}, {2, 3, 4}}, motion);
  for (int k = 0; k < 100; ++k)
    wall.advance(1e-4);
  std::vector<Vector> x, v;
  wall.skin_positions(x);
  wall.skin_velocities(v);
  for (int i = 0; i < 5; ++i)
  {
    CHECK((x[i] - x0[i]).norm() == 0);
    const Vector expected = -133 * Vector(0, 0, 1).cross(x0[i]);
    CHECK((v[i] - expected).norm() < 1e-12 * expected.norm());
    CHECK(std::abs(v[i].dot(Vector(x0[i][0], x0[i][1], 0))) < 1e-15); // tangential
  }
  // A unit tangential force at every vertex: torque = n r about the axis.
  std::vector<Vector> f;
  for (const auto& p : x0)
    f.push_back(Vector(-p[1], p[0], 0) / radius);
  wall.set_skin_forces(f);
  const auto probes = wall.extra_probes();
  CHECK(std::abs(probes[3].second - 5 * radius) < 1e-15);
}

TEST_CASE("a paddle turning in a closed box: fluid momentum = drive + box impulse", "[coupling]")
{
  using Vector = Eigen::Vector2d;
  sph::CaseDescription<2> c;
  c.fluid.particle_spacing = 0.005;
  c.fluid.speed_of_sound = 20;
  c.fluid.gravity = Vector::Zero();
  c.fluid.scheme = sph::TimeScheme::symplectic;
  c.tank.min = Vector(0, 0);
  c.tank.max = Vector(0.2, 0.2);
  c.tank.open_top = false;
  c.fluid_blocks.push_back({Vector(0, 0), Vector(0.2, 0.2)});
  c.hydrostatic_start = false;
  auto fluid = sph::build_fluid(c);

  // A thin closed paddle (0.08 x 0.01 m outline, counter-clockwise) turning at 5 rad/s
  // about the box centre, off-centre so that it pushes the water as a whole too.
  const std::vector<Vector> outline = {{0.06, 0.095}, {0.14, 0.095}, {0.14, 0.105}, {0.06, 0.105}};
  coupling::PrescribedMotion<2> motion;
  motion.centre = Vector(0.08, 0.1);
  motion.angular_speed = 5;
  coupling::PrescribedMotionBody<2> paddle(outline, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, motion);

  coupling::CoSimulation<2> cosim(*fluid);
  cosim.add_body(paddle, "paddle", sph::WallModel::lennard_jones);
  Vector box_impulse = Vector::Zero();
  fluid->add_hook(sph::HookPoint::after_step,
                  [&](sph::FluidSolver<2>& f)
                  {
                    for (const auto& force : f.wall_vertex_forces(0))
                      box_impulse += f.last_time_step() * force;
                  });
  const Vector p0 = cosim.fluid_momentum();
  double largest = 0;
  for (int step = 0; step < 300; ++step)
  {
    cosim.step();
    largest = std::max(largest, paddle.linear_momentum().norm());
  }
  // The fluid gains what the paddle's drive and the box walls put in: the paddle's
  // linear_momentum() is the impulse the fluid gave it, i.e. minus what it gave.
  const Vector drift = cosim.fluid_momentum() - p0 + paddle.linear_momentum() + box_impulse;
  INFO("drift " << drift.transpose() << " paddle impulse " << paddle.linear_momentum().transpose()
                << " box " << box_impulse.transpose());
  CHECK(largest > 1e-3); // the paddle really pushed (N s per metre)
  CHECK(drift.norm() < 2e-5 * largest);
  const auto probes = paddle.extra_probes();
  REQUIRE(probes.size() == 3);
  CHECK(probes[2].first == "torque_Nm");
  CHECK(probes[2].second < 0); // the water resists the counter-clockwise turn
}
