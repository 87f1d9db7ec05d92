// A clamped flexible plate holding back a water column deflects as the FE static
// solution under the same hydrostatic pressure. Reference: statics of the reduced FE
// body, K_red q = Psi^T f with f the consistent nodal loads of p(y) = rho g (H - y) on
// the wetted face, itself checked against Euler-Bernoulli for a cantilever under a
// triangular load (tip: q0 H^4 / (30 EI) + q0 H^3 (L - H) / (24 EI)).
//
// The coupled run: a vertical plate (0.1 m x 5 mm, E = 1.2e8 Pa so that it bends by
// ~1 % of its length and the column's depth stays put), clamped to the tank floor, with
// 0.08 m of water against its left face (hydrostatic start) and air to its right. The
// plate carries modal damping (zeta = 0.7) so that the released load settles within the
// run; the mean tip displacement late in the run must match the static solution within
// 5 %. The path checked is the product's: `chipflex reduce`'s body file read back by the
// body factory, the Lennard-Jones skin, the fluid's reactions mapped through Psi^T.

#include "common/reduced_body_file.h"
#include "coupling/co_simulation.h"
#include "coupling/multibody_coupled_body.h"
#include "fem_test_support.h"
#include "mbs/floating_frame_body.h"
#include "sph/case_setup.h"

#include <catch2/catch.hpp>

using namespace chipflex;
using Vector = Eigen::Vector2d;

namespace
{
constexpr double thickness = 0.005, length = 0.1, depth = 0.08, wall_x = 0.1;
constexpr double rho = 1000, g = 9.81;

fem::Material stiff_plate()
{
  fem::Material m;
  m.youngs_modulus = 1.2e8;
  return m;
}

/// The plate in its file's frame: x in [0, t] (x = 0 wetted), y in [0, L], clamp at y = 0.
std::string plate_body_file()
{
  meshes::BlockMeshSpec spec;
  spec.dim = 2;
  spec.extent = {thickness, length, 0};
  spec.long_axis = 1;
  spec.clamp_at_max = false;
  spec.size = thickness / 4;
  const std::string mesh = fem::testing::scratch("plate_under_column.msh");
  meshes::write_block_mesh(spec, mesh);
  fem::ReductionSettings s;
  s.mesh_file = mesh;
  s.material = stiff_plate();
  s.clamp_group = "clamp";
  s.n_modes = 8;
  s.static_modes = {"pressure:xmin"};
  const std::string file = fem::testing::scratch("plate_under_column.h5");
  write_reduced_body(file, fem::reduce_body(s));
  return file;
}

/// Static x displacement of the tip (mean of the `tip` set) of the reduced body under
/// p(y) = rho g (H - y) on its x = 0 face: consistent nodal loads of the linear shape
/// functions on the skin segments (2-point Gauss on each piece below and above the
/// surface, exact for the piecewise-linear pressure).
double static_tip_displacement(const ReducedBodyData& data)
{
  mbs::FloatingFrameBody<2> body(data);
  body.clamp_to_ground();
  const auto& ids = body.skin_node_ids();
  std::vector<Vector> f(ids.size(), Vector::Zero());
  const double tol = 1e-9;
  for (const auto& face : body.skin_faces())
  {
    const Vector a = body.reference_position(ids[face[0]]),
                 b = body.reference_position(ids[face[1]]);
    if (std::abs(a.x()) > tol || std::abs(b.x()) > tol)
      continue;
    const double ya = a.y(), yb = b.y();
    auto p = [](double y) { return rho * g * std::max(0.0, depth - y); };
    // A segment that crosses the surface is split there (the load is only piecewise linear).
    const double lo = std::min(ya, yb), hi = std::max(ya, yb), cut = std::clamp(depth, lo, hi);
    double fa = 0, fb = 0; // consistent loads of the linear shape functions
    auto add_piece = [&](double y0, double y1)
    {
      if (y1 <= y0)
        return;
      for (double gauss : {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)})
      {
        const double y = 0.5 * (y0 + y1) + 0.5 * (y1 - y0) * gauss, w = 0.5 * (y1 - y0);
        const double na = (yb - y) / (yb - ya); // shape function of node a
        fa += w * na * p(y);
        fb += w * (1 - na) * p(y);
      }
    };
    add_piece(lo, cut);
    add_piece(cut, hi);
    f[face[0]].x() += fa; // pressure on the x = 0 face pushes towards +x
    f[face[1]].x() += fb;
  }
  body.set_skin_forces(f);
  const int m = body.n_modes();
  Eigen::VectorXd load(m);
  body.forces(Vector::Zero(), load); // Psi^T f at q = 0
  const Eigen::VectorXd q = data.stiffness_matrix.ldlt().solve(load);
  body.set_modal_state(q, Eigen::VectorXd::Zero(m));
  double u = 0;
  for (int i : body.node_set("tip"))
    u += body.node_displacement(i).x();
  return u / double(body.node_set("tip").size());
}
} // namespace

TEST_CASE("a clamped plate under a water column deflects as the FE static solution", "[coupling]")
{
  const std::string file = plate_body_file();
  const ReducedBodyData data = read_reduced_body(file);
  const double reference = static_tip_displacement(data);
  const fem::Material material = stiff_plate();
  const double ei = material.youngs_modulus / (1 - std::pow(material.poisson_ratio, 2)) *
                    std::pow(thickness, 3) / 12;
  const double q0 = rho * g * depth;
  const double beam =
      q0 * std::pow(depth, 4) / (30 * ei) + q0 * std::pow(depth, 3) * (length - depth) / (24 * ei);
  INFO("static tip: reduced FE " << reference << " m, Euler-Bernoulli " << beam << " m");
  REQUIRE(reference == Approx(beam).epsilon(0.03));

  sph::CaseDescription<2> c;
  c.fluid.particle_spacing = 0.002;
  c.fluid.reference_density = rho;
  c.fluid.gravity = Vector(0, -g);
  c.fluid.scheme = sph::TimeScheme::symplectic;
  c.sound_coefficient = 20;
  c.tank.min = Vector(0, 0);
  c.tank.max = Vector(0.2, 0.15);
  c.fluid_blocks.push_back({Vector(0, 0), Vector(wall_x, depth)});
  auto fluid = sph::build_fluid(c);

  mbs::FloatingFrameOptions options;
  options.damping = mbs::DampingKind::modal;
  options.modal_damping_ratio = 0.7;
  auto system = std::make_unique<mbs::MultibodySystem<2>>(mbs::IntegratorOptions{});
  system->set_gravity(c.fluid.gravity);
  auto flexible = std::make_unique<mbs::FloatingFrameBody<2>>(read_reduced_body(file), options);
  const std::vector<int> tip = flexible->node_set("tip");
  flexible->set_pose(Vector(wall_x, 0), 0.0);
  flexible->clamp_to_ground();
  auto* skin_body = flexible.get();
  system->add_body(std::move(flexible));
  auto plate = std::make_unique<coupling::MultibodyCoupledBody<2>>(
      "flexible", std::move(system), *skin_body, 0,
      [tip](const mbs::MultibodySystem<2>& s)
      {
        Vector sum = Vector::Zero();
        for (int n : tip)
          sum += s.body(0).node_position(n);
        return Vector(sum / double(tip.size()));
      });
  const Vector tip0 = plate->probe_position();

  coupling::CoSimulation<2> cosim(*fluid);
  cosim.add_body(*plate, "plate", sph::WallModel::lennard_jones);
  double sum = 0, weight = 0;
  while (cosim.time() < 0.6)
  {
    const double dt = cosim.step();
    if (cosim.time() >= 0.3)
    {
      sum += dt * (plate->probe_position() - tip0).x();
      weight += dt;
    }
  }
  const double measured = sum / weight;
  INFO("coupled tip displacement " << measured << " m, static FE " << reference << " m");
  CHECK(measured == Approx(reference).epsilon(0.05));
}
