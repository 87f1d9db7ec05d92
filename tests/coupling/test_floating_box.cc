// A free rigid box floating in the SPH water settles at the draft Archimedes predicts:
// a box of density rho_b and height H_b in water of density rho_w floats with
//   draft d = (rho_b / rho_w) H_b        (per metre of depth, flat and upright).
// Reference: hydrostatics (buoyancy = weight of the displaced water). This checks the
// whole coupling path at once: the Lennard-Jones skin of a body, the fluid's reaction
// forces on the skin nodes, their mapping to the body's resultant and moment, and the
// body step in the co-simulation loop. A wall that let particles through, a reaction
// with the wrong weight or a lost force would all move the draft by more than 2 %.
//
// Measurement: the box (0.1 x 0.048 m, 500 kg/m^3: d = 24 mm) starts at that draft in
// a 0.3 m wide, 0.1 m deep basin whose water fills the space around it (hydrostatic start). A box
// that found too little or too much buoyancy sinks or rises to its own draft; the draft
// measured is the mean of (water level - box bottom) over 0.4 ... 1.6 s, the heave
// oscillation it starts with being small and averaged out. The water level stays the
// initial one: the basin's water volume and the box's displacement are unchanged.
//
// Measured (symplectic fluid): with the dummy-particle skin the draft is 23.99 mm at
// dp = 4 mm (-0.05 %). With the Lennard-Jones skin it is 24.73 mm at dp = 4 mm (+3.1 %)
// and 24.43 mm at dp = 2 mm (+1.8 %): the excess halves with dp, an O(dp) offset of the
// fluid's edge at a Lennard-Jones skin (we attribute it to the first particle layer
// sitting closer than the r0 = dp/2 its volume needs; not measured apart). So the 2 %
// check runs on the dummy-particle skin, and the Lennard-Jones skin is held to a band of
// 5 % either way around Archimedes (re-measured: 24.73 to 24.80 mm, +3.1 to +3.3 %): a fix
// of that offset passes, a lost or doubled buoyancy (a factor of two in the draft) fails.
// Both at dp = 4 mm (~40 s each).

#include "coupling/co_simulation.h"
#include "coupling/multibody_coupled_body.h"
#include "coupling/rigid_shapes.h"
#include "mbs/rigid_body.h"
#include "sph/case_setup.h"

#include <catch2/catch.hpp>

using namespace chipflex;
using Vector = Eigen::Vector2d;

namespace
{
struct Draft
{
  double mean, expected, drift;
};

/// The floating box of the header, its skin seen by the fluid as `skin`.
Draft floating_draft(sph::WallModel skin, double dp)
{
  // Multiples of the spacing: the fluid blocks meet the box faces on the lattice.
  const double basin_width = 0.3, depth = 0.1;
  const double box_width = 0.1, box_height = 0.048, box_density = 500, water = 1000;
  const double expected = box_density / water * box_height;
  const double left = 0.1, right = left + box_width, bottom0 = depth - expected;

  sph::CaseDescription<2> c;
  c.fluid.particle_spacing = dp;
  c.fluid.reference_density = water;
  c.fluid.gravity = Vector(0, -9.81);
  c.fluid.scheme = sph::TimeScheme::symplectic; // the coupling's exact momentum exchange
  c.sound_coefficient = 20;
  c.tank.min = Vector(0, 0);
  c.tank.max = Vector(basin_width, 0.25);
  c.fluid_blocks.push_back({Vector(0, 0), Vector(left, depth)});
  c.fluid_blocks.push_back({Vector(right, 0), Vector(basin_width, depth)});
  c.fluid_blocks.push_back({Vector(left, 0), Vector(right, bottom0)});
  auto fluid = sph::build_fluid(c);

  // Skin nodes a quarter of the box height apart, so the fluid's reaction is resolved
  // along the faces.
  const auto shape =
      coupling::box_shape<2>(Vector(box_width, box_height), box_density, box_height / 4);
  auto system = std::make_unique<mbs::MultibodySystem<2>>(mbs::IntegratorOptions{});
  system->set_gravity(c.fluid.gravity);
  auto rigid = mbs::make_rigid_body<2>(mbs::rigid_body_data<2>(
      shape.mass, shape.centre_of_mass, shape.inertia, shape.nodes, shape.faces));
  rigid->set_pose(Vector(0.5 * (left + right), bottom0 + box_height / 2), 0.0);
  auto* skin_body = rigid.get();
  system->add_body(std::move(rigid));
  auto box =
      std::make_unique<coupling::MultibodyCoupledBody<2>>("rigid", std::move(system), *skin_body);

  coupling::CoSimulation<2> cosim(*fluid);
  cosim.add_body(*box, "box", skin);

  double sum = 0, weight = 0, lowest = 1, highest = 0, drift = 0;
  while (cosim.time() < 1.6)
  {
    const double dt = cosim.step();
    if (cosim.time() < 0.4)
      continue;
    const double bottom = box->probe_position().y() - box_height / 2;
    sum += dt * bottom;
    weight += dt;
    lowest = std::min(lowest, bottom);
    highest = std::max(highest, bottom);
    drift = std::max(drift, std::abs(box->probe_position().x() - 0.5 * (left + right)));
  }
  const double bottom = sum / weight;
  UNSCOPED_INFO("mean box bottom " << bottom << " m (range " << lowest << " ... " << highest
                                   << "), draft " << depth - bottom << " m, Archimedes " << expected
                                   << " m, drift " << drift << " m");
  return {depth - bottom, expected, drift};
}
} // namespace

TEST_CASE("a floating rigid box settles at the draft buoyancy predicts", "[coupling]")
{
  const Draft d = floating_draft(sph::WallModel::dummy_particles, 0.004);
  CHECK(d.mean == Approx(d.expected).epsilon(0.02));
  CHECK(d.drift < 0.02); // it floats in place
}

TEST_CASE("a floating box with a Lennard-Jones skin: draft within its O(dp) offset", "[coupling]")
{
  const Draft d = floating_draft(sph::WallModel::lennard_jones, 0.004);
  CHECK(d.mean == Approx(d.expected).epsilon(0.05));
  CHECK(d.drift < 0.02);
}
