// Conservation of momentum through the coupling (docs/coupling.md, "Weights": the
// reaction forces go back to the skin nodes with the weights that distributed them).
// Reference: Newton's third law. In a closed box without gravity, a free-floating flexible
// body (a reduced truss strip, tests/mbs/truss_beam.h, with elastic modes) falls into a
// moving block of water; the fluid also hits the box. The momentum of fluid + body + the impulse
// the box walls took up (from the fluid's own reaction report) must stay constant to the fluid's
// float round-off, while several percent of it is exchanged.
//
// Exactly so when the body turns a load held over a step into exactly that impulse:
// the symplectic-Euler body step does (frame at the centre of mass, modes
// mass-orthogonal to the rigid motion, so p = m R'). The generalised-alpha step mixes
// the previous step's load into the next (its alpha_f weighting): the momentum then
// lags by a bounded few steps' impulse and does not drift — tested separately.

#include "coupling/co_simulation.h"
#include "coupling/multibody_coupled_body.h"
#include "sph/case_setup.h"
#include "truss_beam.h"

#include <catch2/catch.hpp>

using namespace chipflex;
using Vector = Eigen::Vector2d;

namespace
{
sph::CaseDescription<2> closed_box(sph::WallModel model, sph::TimeScheme fluid_scheme)
{
  sph::CaseDescription<2> c;
  c.fluid.particle_spacing = 0.005;
  c.fluid.speed_of_sound = 20;
  c.fluid.gravity = Vector::Zero();
  c.fluid.scheme = fluid_scheme; // a symplectic scheme: it reports exact reactions
  c.tank.min = Vector(0, 0);
  c.tank.max = Vector(0.3, 0.2);
  c.tank.open_top = false;
  c.tank.model = model;
  c.fluid_blocks.push_back({Vector(0, 0.02), Vector(0.1, 0.12)});
  c.hydrostatic_start = false;
  return c;
}

/// The free-free truss strip with its frame moved to the centre of mass. With modes
/// mass-orthogonal to translation (T = 0) only c_xx and the centre change:
/// C(x - c, x - c) = C(x, x) - m c c^T, C(x - c, psi_k) = C(x, psi_k) - c T_k^T.
ReducedBodyData centred_free_strip()
{
  mbs::test::TrussBeamSpec spec;
  spec.clamped = false;
  spec.n_modes = 4;
  auto body = mbs::test::make_truss_beam(spec).body;
  REQUIRE(body.translation_coupling.norm() < 1e-9 * body.mass);
  const Eigen::Vector2d c = body.center_of_mass;
  for (int i = 0; i < body.n_nodes(); ++i)
    body.nodes.row(i) -= c.transpose();
  body.c_xx -= body.mass * c * c.transpose();
  body.center_of_mass.setZero();
  return body;
}

void check_momentum(sph::WallModel model, mbs::IntegratorOptions::Scheme scheme,
                    sph::TimeScheme fluid_scheme = sph::TimeScheme::symplectic)
{
  // A thin-skin body in a box of dummy particles.
  auto description = closed_box(
      model == sph::WallModel::thin_skin ? sph::WallModel::dummy_particles : model, fluid_scheme);
  auto fluid = sph::build_fluid(description);
  // The water moves left into the box wall, the body falls onto the water.
  for (std::size_t i = fluid->n_boundary(); i < fluid->n_particles(); ++i)
    fluid->particles().velocity[0][i] = -0.5f;

  mbs::IntegratorOptions options;
  options.scheme = scheme;
  auto system = std::make_unique<mbs::MultibodySystem<2>>(options);
  auto flexible = std::make_unique<mbs::FloatingFrameBody<2>>(centred_free_strip());
  flexible->set_pose(Vector(0.06, 0.128), 0.0);
  flexible->set_frame_velocity(Vector(0.1, -0.8), Eigen::Matrix<double, 1, 1>(2.0));
  auto* skin = flexible.get();
  system->add_body(std::move(flexible));
  coupling::MultibodyCoupledBody<2> body("flexible", std::move(system), *skin);

  coupling::CoSimulation<2> cosim(*fluid);
  cosim.add_body(body, "strip", model);
  Vector box_impulse = Vector::Zero();
  fluid->add_hook(sph::HookPoint::after_step,
                  [&](sph::FluidSolver<2>& f)
                  {
                    for (const auto& force : f.wall_vertex_forces(0)) // wall 0: the tank
                      box_impulse += f.last_time_step() * force;
                  });

  const Vector p0 = cosim.total_momentum();
  const Vector body0 = body.linear_momentum();
  double largest = p0.norm(), largest_impulse = 0;
  for (int step = 0; step < 400; ++step)
  {
    cosim.step();
    largest = std::max(largest, cosim.fluid_momentum().norm());
    Vector f = Vector::Zero();
    for (const auto& force : fluid->wall_vertex_forces(cosim.fluid_wall_id(0)))
      f += force;
    largest_impulse = std::max(largest_impulse, fluid->last_time_step() * f.norm());
  }
  const Vector drift = cosim.total_momentum() + box_impulse - p0;
  const double exchanged = (body.linear_momentum() - body0).norm();
  INFO("drift " << drift.transpose() << " exchanged with body " << exchanged << " box "
                << box_impulse.transpose() << " scale " << largest);
  CHECK(exchanged > 0.05 * body0.norm()); // the body really was pushed by the water
  CHECK(box_impulse.norm() > 0.05 * largest);
  if (scheme == mbs::IntegratorOptions::Scheme::symplectic_euler)
    CHECK(drift.norm() < 2e-5 * largest); // float velocities in the fluid: ~1e-7 each
  else
    CHECK(drift.norm() < 3 * largest_impulse); // a bounded lag, not a drift
}
} // namespace

TEST_CASE("closed box, no gravity: fluid + flexible body momentum conserved (LJ walls)",
          "[coupling]")
{
  check_momentum(sph::WallModel::lennard_jones, mbs::IntegratorOptions::Scheme::symplectic_euler);
}

TEST_CASE("closed box, no gravity: generalised-alpha body lags, does not drift", "[coupling]")
{
  check_momentum(sph::WallModel::lennard_jones, mbs::IntegratorOptions::Scheme::generalized_alpha);
}

TEST_CASE("closed box, no gravity: fluid + flexible body momentum conserved (dummy walls)",
          "[coupling]")
{
  check_momentum(sph::WallModel::dummy_particles, mbs::IntegratorOptions::Scheme::symplectic_euler);
}

// The strip as a thin skin (sided dummy particles, the visibility mask and the guard,
// sph/thin_skins.h): fluid reaches it from both sides, and every pair the mask leaves
// out is left out for both partners, so the exchange stays exact.
TEST_CASE("closed box, no gravity: fluid + flexible body momentum conserved (thin skin)",
          "[coupling]")
{
  check_momentum(sph::WallModel::thin_skin, mbs::IntegratorOptions::Scheme::symplectic_euler);
}

TEST_CASE("closed box, no gravity: momentum conserved with the one-pass position Verlet fluid",
          "[coupling]")
{
  check_momentum(sph::WallModel::lennard_jones, mbs::IntegratorOptions::Scheme::symplectic_euler,
                 sph::TimeScheme::position_verlet);
}

TEST_CASE("closed 3D box, no gravity: fluid + free flexible body momentum conserved", "[coupling]")
{
  using Vector3 = Eigen::Vector3d;
  sph::CaseDescription<3> c;
  c.fluid.particle_spacing = 0.01;
  c.fluid.speed_of_sound = 20;
  c.fluid.gravity = Vector3::Zero();
  c.fluid.scheme = sph::TimeScheme::symplectic;
  c.tank.min = Vector3(0, 0, 0);
  c.tank.max = Vector3(0.3, 0.12, 0.2);
  c.tank.open_top = false;
  c.tank.model = sph::WallModel::lennard_jones;
  c.fluid_blocks.push_back({Vector3(0, 0, 0.02), Vector3(0.1, 0.12, 0.12)});
  c.hydrostatic_start = false;
  auto fluid = sph::build_fluid(c);
  for (std::size_t i = fluid->n_boundary(); i < fluid->n_particles(); ++i)
    fluid->particles().velocity[0][i] = -0.5f;

  // A free 3D truss strip (elastic modes, frame at the centre of mass) thrown into the water.
  mbs::test::TrussBeamSpec spec;
  spec.dim = 3;
  spec.clamped = false;
  spec.n_cells = 8;
  spec.length = 0.08;
  spec.height = 0.02;
  spec.depth = 0.04;
  spec.n_modes = 4;
  auto data = mbs::test::make_truss_beam(spec).body;
  const Vector3 com = data.center_of_mass;
  for (int i = 0; i < data.n_nodes(); ++i)
    data.nodes.row(i) -= com.transpose();
  data.c_xx -= data.mass * com * com.transpose();
  data.center_of_mass.setZero();
  mbs::IntegratorOptions options;
  options.scheme = mbs::IntegratorOptions::Scheme::symplectic_euler;
  auto system = std::make_unique<mbs::MultibodySystem<3>>(options);
  auto flexible = std::make_unique<mbs::FloatingFrameBody<3>>(data);
  flexible->set_pose(Vector3(0.06, 0.06, 0.14), Eigen::Matrix3d::Identity());
  flexible->set_frame_velocity(Vector3(0.1, 0.0, -0.8), Vector3(0.5, 2.0, 0.0));
  auto* skin = flexible.get();
  system->add_body(std::move(flexible));
  // The explicit body step sub-steps below its stiffest kept mode's stability limit.
  coupling::MultibodyCoupledBody<3> body("flexible", std::move(system), *skin, 2e-6);

  coupling::CoSimulation<3> cosim(*fluid);
  cosim.add_body(body, "strip", sph::WallModel::lennard_jones);
  Vector3 box_impulse = Vector3::Zero();
  fluid->add_hook(sph::HookPoint::after_step,
                  [&](sph::FluidSolver<3>& f)
                  {
                    for (const auto& force : f.wall_vertex_forces(0))
                      box_impulse += f.last_time_step() * force;
                  });
  const Vector3 p0 = cosim.total_momentum();
  const Vector3 body0 = body.linear_momentum();
  double largest = p0.norm();
  for (int step = 0; step < 250; ++step)
  {
    cosim.step();
    largest = std::max(largest, cosim.fluid_momentum().norm());
  }
  const Vector3 drift = cosim.total_momentum() + box_impulse - p0;
  const double exchanged = (body.linear_momentum() - body0).norm();
  INFO("drift " << drift.transpose() << " exchanged with body " << exchanged << " box "
                << box_impulse.transpose() << " scale " << largest);
  CHECK(exchanged > 0.05 * body0.norm());
  CHECK(box_impulse.norm() > 0.02 * largest); // the water hit the box wall too
  CHECK(drift.norm() < 2e-5 * largest);
}
