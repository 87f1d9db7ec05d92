// Contact in the coupled loop (coupling::CoSimulation::enable_contact) and the
// fluid-permeable barrier (sph::WallSurface::fluid_passes).
//
// - A block of water thrown at a wall without gravity: a wall the fluid feels turns it
//   back, a permeable barrier leaves its momentum unchanged (nothing acts on it).
// - A chip-like steel strip (a free reduced truss strip, tests/mbs/truss_beam.h) falls
//   into water, sinks through it and comes to rest on a permeable barrier that spans the
//   tank at mid-depth: it ends at rest (skin speeds ~ 0) with its lowest skin node on
//   the barrier (within the contact's overlap), far above the tank floor it would reach
//   without the barrier, while the water below the barrier stays there.

#include "common/hdf5_file.h"
#include "coupling/co_simulation.h"
#include "coupling/multibody_coupled_body.h"
#include "sph/case_setup.h"
#include "truss_beam.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>

using namespace chipflex;
using Vector = Eigen::Vector2d;

namespace
{
/// A horizontal wall across the tank at height y, bodies (and fluid) above it.
sph::WallSurface<2> barrier(double y, double x0, double x1, bool fluid_passes)
{
  sph::WallSurface<2> w;
  w.name = "barrier";
  w.model = sph::WallModel::lennard_jones;
  w.vertices = {Vector(x1, y), Vector(x0, y)}; // right of x1 -> x0: up
  w.faces = {{0, 1}};
  w.fluid_passes = fluid_passes;
  return w;
}

/// Momentum of a block of water thrown down at 1 m/s onto a barrier 2 cm below it,
/// after 0.06 s, as a fraction of the initial momentum.
double momentum_left(bool fluid_passes)
{
  sph::CaseDescription<2> c;
  c.fluid.particle_spacing = 0.004;
  c.fluid.speed_of_sound = 20;
  c.fluid.gravity = Vector::Zero();
  c.fluid.scheme = sph::TimeScheme::symplectic; // starts from the velocities set below
  c.tank.enabled = false;
  c.fluid_blocks.push_back({Vector(0, 0.02), Vector(0.04, 0.06)});
  c.walls.push_back(barrier(0.0, -0.05, 0.09, fluid_passes));
  c.hydrostatic_start = false;
  c.automatic_domain = false; // room below the barrier for the water that passes it
  c.fluid.domain_min = Vector(-1, -1);
  c.fluid.domain_max = Vector(1, 1);
  auto fluid = sph::build_fluid(c);
  fluid->initialise();
  for (std::size_t i = fluid->n_boundary(); i < fluid->n_particles(); ++i)
    fluid->particles().velocity[1][i] = -1.0f;
  auto momentum = [&]()
  {
    double p = 0;
    for (std::size_t i = fluid->n_boundary(); i < fluid->n_particles(); ++i)
      p += fluid->particles().velocity[1][i];
    return p;
  };
  const double p0 = momentum();
  while (fluid->time() < 0.06)
    fluid->step();
  return momentum() / p0;
}
} // namespace

TEST_CASE("a permeable barrier does not act on the fluid", "[coupling][contact]")
{
  const double passes = momentum_left(true), wall = momentum_left(false);
  INFO("momentum left after 0.06 s: barrier " << passes << ", wall " << wall);
  CHECK(passes == Approx(1.0).margin(1e-5)); // free flight without gravity
  CHECK(wall < 0.5);                         // a wall the fluid feels stops it
}

namespace
{
/// The strip of the header over a barrier at y_barrier, in 6 cm of water.
struct StripOnBarrier
{
  static constexpr double width = 0.15, depth = 0.06, dp = 0.003, y_barrier = 0.024;
  std::unique_ptr<sph::FluidSolver<2>> fluid;
  std::unique_ptr<coupling::MultibodyCoupledBody<2>> body;
  mbs::FloatingFrameBody<2>* skin = nullptr;
  std::unique_ptr<coupling::CoSimulation<2>> cosim;

  StripOnBarrier()
  {
    sph::CaseDescription<2> c;
    c.fluid.particle_spacing = dp;
    c.fluid.gravity = Vector(0, -9.81);
    c.fluid.scheme = sph::TimeScheme::symplectic;
    c.tank.min = Vector(0, 0);
    c.tank.max = Vector(width, 0.12);
    c.fluid_blocks.push_back({Vector(0, 0), Vector(width, depth)});
    c.walls.push_back(barrier(y_barrier, 0, width, true));
    fluid = sph::build_fluid(c);

    // A steel strip 40 x 4 mm, tilted by 0.2 rad, starting 1.5 cm above the water.
    mbs::test::TrussBeamSpec spec;
    spec.clamped = false;
    spec.n_modes = 4;
    spec.length = 0.04;
    spec.height = 0.004;
    spec.n_cells = 8;
    spec.density = 7800;
    auto system = std::make_unique<mbs::MultibodySystem<2>>();
    system->set_gravity(c.fluid.gravity);
    auto strip = std::make_unique<mbs::FloatingFrameBody<2>>(mbs::test::make_truss_beam(spec).body);
    strip->set_pose(Vector(0.055, depth + 0.015), -0.2);
    skin = strip.get();
    system->add_body(std::move(strip));
    body =
        std::make_unique<coupling::MultibodyCoupledBody<2>>("flexible", std::move(system), *skin);

    cosim = std::make_unique<coupling::CoSimulation<2>>(*fluid);
    cosim->add_body(*body, "strip", sph::WallModel::lennard_jones);
    coupling::ContactParameters contact;
    contact.restitution = 0.3;
    contact.friction = 0.4;
    cosim->enable_contact(contact);
  }
};
} // namespace

TEST_CASE("a chip-like strip sinks through water and rests on a permeable barrier",
          "[coupling][contact][heavy]")
{
  StripOnBarrier run;
  auto& fluid = run.fluid;
  auto& cosim = run.cosim;
  auto* skin = run.skin;
  const double y_barrier = StripOnBarrier::y_barrier;
  auto below_barrier = [&]()
  {
    int n = 0;
    for (std::size_t i = fluid->n_boundary(); i < fluid->n_particles(); ++i)
      n += fluid->position(i).y() < y_barrier;
    return n;
  };
  const int below0 = below_barrier();
  double max_overlap = 0, speed_sum = 0, time_sum = 0;
  Vector lo = Vector::Constant(1), hi = Vector::Constant(-1);
  bool touched = false;
  std::vector<Vector> x, v;
  while (cosim->time() < 0.5)
  {
    const double dt = cosim->step();
    touched = touched || cosim->contact()->n_contacts() > 0;
    max_overlap = std::max(max_overlap, cosim->contact()->max_overlap());
    if (cosim->time() > 0.3)
    {
      // At rest: the frame stays put, and the skin's fastest node is slow on average
      // (the water's pressure noise at dp = 3 mm rocks it by a few mm/s now and then).
      lo = lo.cwiseMin(skin->position());
      hi = hi.cwiseMax(skin->position());
      skin->skin_velocities(v);
      double fastest = 0;
      for (const auto& vi : v)
        fastest = std::max(fastest, vi.norm());
      speed_sum += dt * fastest;
      time_sum += dt;
    }
  }
  const double mean_speed = speed_sum / time_sum;
  skin->skin_positions(x);
  double lowest = 1, highest = 0;
  for (const auto& xi : x)
  {
    lowest = std::min(lowest, xi.y());
    highest = std::max(highest, xi.y());
  }
  const int below1 = below_barrier();
  INFO("strip lowest " << lowest << " m, highest " << highest << " m (barrier " << y_barrier
                       << "), max overlap " << max_overlap
                       << " m, 0.3 ... 0.5 s: mean fastest skin speed " << mean_speed
                       << " m/s, frame moved by " << (hi - lo).transpose()
                       << " m, fluid below the barrier " << below0 << " -> " << below1
                       << ", lost particles " << fluid->lost_particles().size());
  REQUIRE(touched);
  CHECK(lowest > y_barrier - std::max(max_overlap, 1e-4));
  CHECK(lowest < y_barrier + 0.5e-3);
  CHECK(highest < y_barrier + 0.006); // it lies flat (4 mm thick)
  CHECK(mean_speed < 0.01);           // it falls at 0.4 m/s
  CHECK((hi - lo).norm() < 1e-3);     // 0.2 s of sinking would take it 8 cm
  CHECK(std::abs(below1 - below0) < 0.05 * below0);
  CHECK(fluid->lost_particles().empty());
}

TEST_CASE("a coupled run with contact restarts bitwise", "[coupling][contact]")
{
  // Checkpoint while the strip lies on the barrier with its tangential springs loaded.
  // The step at which a contact exists depends on the CPU's floating-point path
  // (-march=native), so step from 0.2 s on until one does rather than expecting one at a
  // fixed step; then both runs count the steps with contacts after the checkpoint.
  StripOnBarrier a;
  while (a.cosim->time() < 0.2 || a.cosim->contact()->n_contacts() == 0)
  {
    a.cosim->step();
    REQUIRE(a.cosim->time() < 0.5); // the strip reaches the barrier at about 0.15 s
  }
  const std::string path =
      (std::filesystem::temp_directory_path() / "chipflex_contact_restart.h5").string();
  {
    Hdf5File h5(path, Hdf5File::Mode::create);
    a.cosim->save(h5, "/state");
  }
  const auto contact_at_checkpoint = a.cosim->contact()->state();
  auto step_counting_contacts = [](StripOnBarrier& run)
  {
    std::vector<int> contacts;
    for (int k = 0; k < 300; ++k)
    {
      run.cosim->step();
      contacts.push_back(run.cosim->contact()->n_contacts());
    }
    return contacts;
  };
  const auto contacts_a = step_counting_contacts(a);

  StripOnBarrier b;
  {
    const Hdf5File h5(path, Hdf5File::Mode::read);
    b.cosim->load(h5, "/state");
  }
  std::filesystem::remove(path);
  CHECK(b.cosim->contact()->state() == contact_at_checkpoint); // the loaded springs
  const auto contacts_b = step_counting_contacts(b);
  CHECK(b.cosim->time() == a.cosim->time());
  CHECK(b.body->state() == a.body->state());
  CHECK(b.cosim->contact()->state() == a.cosim->contact()->state());
  CHECK(contacts_b == contacts_a);
  CHECK(std::count_if(contacts_a.begin(), contacts_a.end(), [](int n) { return n > 0; }) > 0);
}
