// Conservation of linear momentum (the pair forces are antisymmetric, and every wall
// reports exactly the reaction it exerts):
//  - a free blob without gravity or walls keeps its momentum;
//  - in a closed box without gravity, fluid momentum + impulse given to the walls
//    (dt * sum of wall vertex forces) stays equal to the initial momentum;
//  - a moving piston wall (Lennard-Jones or dummy particles): the fluid's momentum
//    change equals -sum(wall vertex forces) * dt, step by step.

#include "sph/fluid_solver.h"
#include "sph_test_cases.h"

#include <catch2/catch.hpp>

using namespace chipflex::sph;
using Vector = Eigen::Vector2d;

namespace
{
Vector fluid_momentum(const FluidSolver<2>& f)
{
  Vector p = Vector::Zero();
  for (std::size_t i = f.n_boundary(); i < f.n_particles(); ++i)
    p += f.particle_mass() * f.velocity(i);
  return p;
}

Vector wall_force(const FluidSolver<2>& f)
{
  Vector s = Vector::Zero();
  for (int w = 0; w < f.n_walls(); ++w)
    for (const auto& v : f.wall_vertex_forces(w))
      s += v;
  return s;
}

std::vector<Vector> swirl(const std::vector<Vector>& x)
{
  std::vector<Vector> v;
  for (const auto& p : x)
    v.push_back(Vector(0.6 + std::sin(20 * p[1]), 0.3 * std::cos(15 * p[0])));
  return v;
}
} // namespace

TEST_CASE("a free blob without gravity keeps its momentum", "[sph][conservation]")
{
  const double dp = 0.01;
  auto c = testing::closed_box(dp);
  c.tank.enabled = false;
  c.fluid.domain_min = Vector(-2, -2);
  c.fluid.domain_max = Vector(2, 2);
  c.automatic_domain = false;
  FluidSolver<2> fluid(c.fluid);
  std::vector<Vector> x;
  for (double px = dp / 2; px < 0.3; px += dp)
    for (double py = dp / 2; py < 0.2; py += dp)
      x.push_back(Vector(px, py));
  fluid.add_fluid_particles(x, {}, swirl(x));
  fluid.initialise();
  const Vector p0 = fluid_momentum(fluid);
  for (int s = 0; s < 300; ++s)
    fluid.step();
  const Vector p1 = fluid_momentum(fluid);
  INFO("p0 = " << p0.transpose() << ", p1 = " << p1.transpose());
  CHECK((p1 - p0).norm() < 1e-5 * p0.norm());
}

TEST_CASE("closed box without gravity: fluid momentum plus wall impulse is conserved",
          "[sph][conservation]")
{
  const double dp = 0.01;
  auto c = testing::closed_box(dp);
  c.automatic_domain = false;
  c.fluid.domain_min = Vector(-1, -1);
  c.fluid.domain_max = Vector(1, 1);
  auto built = build_fluid(c);
  built->initialise();
  // Same case, particles with a swirl.
  FluidSolver<2> f(c.fluid);
  f.add_wall(built->wall(0));
  std::vector<Vector> x;
  for (std::size_t i = 0; i < built->n_particles(); ++i)
    x.push_back(built->position(i));
  f.add_fluid_particles(x, {}, swirl(x));
  f.initialise();
  const Vector p0 = fluid_momentum(f);
  Vector impulse = Vector::Zero();
  double largest_impulse = 0;
  while (f.time() < 0.3)
  {
    const double dt = f.step();
    impulse += dt * wall_force(f);
    largest_impulse = std::max(largest_impulse, impulse.norm());
  }
  const Vector p1 = fluid_momentum(f);
  INFO("p0 " << p0.transpose() << " p1 " << p1.transpose() << " wall impulse "
             << impulse.transpose());
  REQUIRE(largest_impulse > 0.2 * p0.norm()); // the walls did take momentum
  CHECK((p1 + impulse - p0).norm() < 1e-4 * p0.norm());
}

TEST_CASE("moving wall reactions balance the fluid's momentum change", "[sph][conservation]")
{
  for (const auto model : {WallModel::lennard_jones, WallModel::dummy_particles})
  {
    DYNAMIC_SECTION("piston model " << int(model))
    {
      const double dp = 0.01;
      auto c = testing::closed_box(dp);
      c.fluid.gravity = Vector(0, -9.81);
      c.fluid.speed_of_sound = 25;
      auto fluid = build_fluid(c);
      fluid->initialise();
      // A vertical piston right of the fluid, normal pointing left (-x), moving left.
      WallSurface<2> piston;
      piston.name = "piston";
      piston.model = model;
      piston.vertices = {Vector(0.305, 0.3), Vector(0.305, -0.02)};
      piston.faces = {{0, 1}};
      FluidSolver<2> f(c.fluid);
      f.add_wall(fluid->wall(0));
      const int id = f.add_wall(piston);
      std::vector<Vector> x;
      std::vector<double> rho;
      for (std::size_t i = fluid->n_boundary(); i < fluid->n_particles(); ++i)
      {
        x.push_back(fluid->position(i));
        rho.push_back(fluid->particles().density[i]);
      }
      f.add_fluid_particles(x, rho);
      const double speed = 0.5;
      f.add_hook(HookPoint::before_forces,
                 [&](FluidSolver<2>& s)
                 {
                   const double shift = -speed * s.time();
                   s.move_wall(id, {Vector(0.305 + shift, 0.3), Vector(0.305 + shift, -0.02)},
                               {Vector(-speed, 0), Vector(-speed, 0)});
                 });
      double worst = 0, scale = 0;
      for (int s = 0; s < 400; ++s)
      {
        const Vector p_before = fluid_momentum(f);
        const double dt = f.step();
        const Vector change = fluid_momentum(f) - p_before;
        const Vector gravity = dt * f.particle_mass() * double(f.n_fluid()) * c.fluid.gravity;
        const Vector walls = -dt * wall_force(f);
        worst = std::max(worst, (change - gravity - walls).norm());
        scale = std::max(scale, walls.norm());
      }
      const Vector piston_force = f.wall_vertex_forces(id)[0] + f.wall_vertex_forces(id)[1];
      INFO("worst mismatch " << worst << " N s, largest wall impulse per step " << scale
                             << ", piston force " << piston_force.transpose());
      REQUIRE(scale > 0);
      CHECK(piston_force[0] > 0); // the fluid pushes the piston back (+x)
      CHECK(worst < 1e-4 * scale);
    }
  }
}
