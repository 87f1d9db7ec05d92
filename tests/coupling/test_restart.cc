// A coupled run restarted from a checkpoint ends in the same state as an uninterrupted
// one (issue 5: "body states included, same final state"). Reference: the uninterrupted
// run itself, bitwise (same thread count, same build).

#include "common/hdf5_file.h"
#include "coupling/co_simulation.h"
#include "coupling/multibody_coupled_body.h"
#include "sph/case_setup.h"
#include "truss_beam.h"

#include <catch2/catch.hpp>
#include <filesystem>

using namespace chipflex;
using Vector = Eigen::Vector2d;

namespace
{
struct Coupled
{
  std::unique_ptr<sph::FluidSolver<2>> fluid;
  std::unique_ptr<coupling::MultibodyCoupledBody<2>> body;
  std::unique_ptr<coupling::CoSimulation<2>> cosim;

  Coupled()
  {
    sph::CaseDescription<2> c;
    c.fluid.particle_spacing = 0.005;
    c.fluid.gravity = Vector(0, -9.81);
    c.fluid.scheme = sph::TimeScheme::symplectic;
    c.tank.min = Vector(0, 0);
    c.tank.max = Vector(0.3, 0.2);
    c.fluid_blocks.push_back({Vector(0, 0), Vector(0.1, 0.1)});
    fluid = sph::build_fluid(c);
    mbs::test::TrussBeamSpec spec; // clamped strip, hanging into the water's path
    spec.n_modes = 4;
    auto system = std::make_unique<mbs::MultibodySystem<2>>();
    system->set_gravity(Vector(0, -9.81));
    auto strip = std::make_unique<mbs::FloatingFrameBody<2>>(mbs::test::make_truss_beam(spec).body);
    strip->set_pose(Vector(0.12, 0.085), -M_PI / 2);
    strip->clamp_to_ground();
    auto* skin = strip.get();
    system->add_body(std::move(strip));
    body =
        std::make_unique<coupling::MultibodyCoupledBody<2>>("flexible", std::move(system), *skin);
    cosim = std::make_unique<coupling::CoSimulation<2>>(*fluid);
    cosim->add_body(*body, "strip", sph::WallModel::lennard_jones);
  }
  void run(int steps)
  {
    for (int k = 0; k < steps; ++k)
      cosim->step();
  }
};
} // namespace

TEST_CASE("coupled checkpoint and restart reproduce the uninterrupted run", "[coupling]")
{
  Coupled a;
  a.run(150);
  // In the system temporary folder: tests never write into the working tree.
  const std::string path =
      (std::filesystem::temp_directory_path() / "chipflex_coupled_checkpoint.h5").string();
  {
    Hdf5File h5(path, Hdf5File::Mode::create);
    a.cosim->save(h5, "/state");
  }
  a.run(150);

  Coupled b;
  {
    const Hdf5File h5(path, Hdf5File::Mode::read);
    b.cosim->load(h5, "/state");
  }
  b.run(150);

  CHECK(b.fluid->time() == a.fluid->time());
  CHECK(b.body->state() == a.body->state());
  CHECK(b.body->probe_position() == a.body->probe_position());
  const auto& pa = a.fluid->particles();
  const auto& pb = b.fluid->particles();
  REQUIRE(pa.size() == pb.size());
  bool same = true;
  for (std::size_t i = 0; i < pa.size(); ++i)
    same = same && pa.position[0][i] == pb.position[0][i] && pa.position[1][i] == pb.position[1][i];
  CHECK(same);
  // The strip really moved (the test is not comparing two resting states).
  CHECK(a.body->system().body(0).modal_coordinates().norm() > 0);
}
