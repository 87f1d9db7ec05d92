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
//
// The thin flap: the same bending stiffness from a steel sheet 0.5 mm = dp/4 thick (E =
// 1.2e11 Pa, nu = 0.3: E t^3 / (1 - nu^2) within 9 % of the rubber plate's), far thinner
// than the kernel support (2h = 5.7 mm), as a thin skin (sph/thin_skins.h): the water on
// its left must not act through it on the air side, and its load must be the hydrostatic
// one.

#include "common/reduced_body_file.h"
#include "coupling/co_simulation.h"
#include "coupling/multibody_coupled_body.h"
#include "fem_test_support.h"
#include "mbs/floating_frame_body.h"
#include "sph/case_setup.h"
#include "sph/dummy_wall_particles.h"

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>

using namespace chipflex;
using Vector = Eigen::Vector2d;

namespace
{
constexpr double thickness = 0.005, length = 0.1, depth = 0.08, wall_x = 0.1;
constexpr double rho = 1000, g = 9.81;

fem::Material stiff_plate()
{
  fem::Material m{1.2e8, 0.4, 1100, false}; // the gate's rubber, ten times as stiff
  return m;
}

/// A 2D plate: thickness, material, skin model.
struct PlateSpec
{
  double thickness;
  fem::Material material;
  sph::WallModel model;
  std::string name;
};

const PlateSpec rubber_plate{thickness, stiff_plate(), sph::WallModel::lennard_jones,
                             "plate_under_column"};
const PlateSpec steel_flap{0.0005, fem::Material{1.2e11, 0.3, 7850, false},
                           sph::WallModel::thin_skin, "thin_flap_under_column"};

/// The plate meshed as `spec` (clamp at its long axis' minimum) and reduced: 8 modes plus
/// the static mode of a pressure on its x = 0 face; returns the body file `name`.h5.
std::string reduced_plate(meshes::BlockMeshSpec spec, const std::string& name,
                          const fem::Material& material = stiff_plate())
{
  spec.clamp_at_max = false;
  const std::string mesh = fem::testing::scratch(name + ".msh");
  meshes::write_block_mesh(spec, mesh);
  fem::ReductionSettings s;
  s.mesh_file = mesh;
  s.material = material;
  s.clamp_group = "clamp";
  s.n_modes = 8;
  s.static_modes = {"pressure:xmin"};
  const std::string file = fem::testing::scratch(name + ".h5");
  write_reduced_body(file, fem::reduce_body(s));
  return file;
}

/// The plate in its file's frame: x in [0, t] (x = 0 wetted), y in [0, L], clamp at y = 0.
/// Two quadratic elements across the thickness at least (the rubber plate four).
std::string plate_body_file(const PlateSpec& plate)
{
  meshes::BlockMeshSpec spec;
  spec.dim = 2;
  spec.extent = {plate.thickness, length, 0};
  spec.long_axis = 1;
  spec.size = plate.thickness >= thickness ? plate.thickness / 4 : plate.thickness / 2;
  return reduced_plate(spec, plate.name, plate.material);
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

/// The 2D plate under the column: the reduced FE static tip (checked against Euler-
/// Bernoulli), and the coupled run's mean tip over [0.3, 0.6] s, within 5 % of it.
void check_plate_2d(const PlateSpec& spec)
{
  const std::string file = plate_body_file(spec);
  const ReducedBodyData data = read_reduced_body(file);
  const double reference = static_tip_displacement(data);
  const fem::Material& material = spec.material;
  const double ei = material.youngs_modulus / (1 - std::pow(material.poisson_ratio, 2)) *
                    std::pow(spec.thickness, 3) / 12;
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
  cosim.add_body(*plate, "plate", spec.model);
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
  std::printf("%s: coupled tip %.4e m, static FE %.4e m (%+.2f %%), guarded %zu\n",
              spec.name.c_str(), measured, reference, 100 * (measured / reference - 1),
              fluid->n_guarded());
  std::fflush(stdout);
  INFO("coupled tip displacement " << measured << " m, static FE " << reference << " m");
  CHECK(measured == Approx(reference).epsilon(0.05));
  // No water on the dry side: every fluid particle stays left of the plate's wet face.
  std::size_t dry = 0;
  for (std::size_t i = fluid->n_boundary(); i < fluid->n_particles(); ++i)
    dry += fluid->position(i).x() > wall_x + 0.02;
  CHECK(dry == 0);
}
} // namespace

TEST_CASE("a clamped plate under a water column deflects as the FE static solution", "[coupling]")
{
  check_plate_2d(rubber_plate);
}

TEST_CASE("a thin steel flap (dp/4) under a water column deflects as the FE static solution",
          "[coupling]")
{
  check_plate_2d(steel_flap);
}

// ---- 3D -----------------------------------------------------------------------------
// The same plate in 3D: 0.1 m high (z), 5 mm thick (x), spanning a 0.04 m wide channel
// (y) between the tank's side walls, clamped to the floor, 0.08 m of water against its
// x = 0 face. Reference: the reduced 3D FE body's static solution under the consistent
// nodal loads of p(z) = rho g (H - z) on that face, itself checked to lie between the
// cantilever-beam deflection with E (free sides, narrow) and with E / (1 - nu^2) (a wide
// plate in cylindrical bending), 3 % either side.
namespace
{
using V3 = Eigen::Vector3d;
constexpr double width = 0.04;

/// The 3D plate: x in [0, t] (x = 0 wetted), y in [0, width], z in [0, L], clamp at z = 0.
/// Elements of 2.5 mm: two across the rubber plate, one (quadratic) across the thin flap.
std::string plate_body_file_3d(const PlateSpec& plate)
{
  meshes::BlockMeshSpec spec;
  spec.dim = 3;
  spec.extent = {plate.thickness, width, length};
  spec.long_axis = 2;
  spec.size = thickness / 2;
  return reduced_plate(spec, plate.name + "_3d", plate.material);
}

/// Static x displacement of the tip (mean of `tip`) under p(z) on the x = 0 face:
/// consistent loads of the linear skin triangles, integrated on 64 sub-triangles each
/// (the pressure's kink at the surface costs < 0.1 %).
double static_tip_displacement_3d(const ReducedBodyData& data)
{
  mbs::FloatingFrameBody<3> body(data);
  body.clamp_to_ground();
  const auto& ids = body.skin_node_ids();
  std::vector<V3> f(ids.size(), V3::Zero());
  const int n = 8;
  for (const auto& face : body.skin_faces())
  {
    const V3 a = body.reference_position(ids[face[0]]), b = body.reference_position(ids[face[1]]),
             c = body.reference_position(ids[face[2]]);
    if (std::abs(a.x()) > 1e-9 || std::abs(b.x()) > 1e-9 || std::abs(c.x()) > 1e-9)
      continue;
    const double area = 0.5 * (b - a).cross(c - a).norm();
    // Centroids of the n^2 sub-triangles of the barycentric grid, equal areas.
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j)
        for (int up = 0; up < (i + j + 1 < n ? 2 : 1); ++up)
        {
          const double u = (i + (up ? 2.0 : 1.0) / 3) / n, v = (j + (up ? 2.0 : 1.0) / 3) / n;
          const double w0 = 1 - u - v;
          const double z = w0 * a.z() + u * b.z() + v * c.z();
          const double load = rho * g * std::max(0.0, depth - z) * area / (n * n);
          f[face[0]].x() += w0 * load;
          f[face[1]].x() += u * load;
          f[face[2]].x() += v * load;
        }
  }
  body.set_skin_forces(f);
  const int m = body.n_modes();
  Eigen::VectorXd load(m);
  body.forces(V3::Zero(), load);
  const Eigen::VectorXd q = data.stiffness_matrix.ldlt().solve(load);
  body.set_modal_state(q, Eigen::VectorXd::Zero(m));
  double u = 0;
  for (int i : body.node_set("tip"))
    u += body.node_displacement(i).x();
  return u / double(body.node_set("tip").size());
}

struct PlateRun3d
{
  double tip = 0;      ///< mean x displacement of the tip over the averaging window, m
  double force = 0;    ///< mean x force of the fluid on the skin there, N
  double moment = 0;   ///< mean moment of that force about the clamp (sum f_x z), N m
  std::size_t dry = 0; ///< fluid particles on the dry side at the end (2 cm past the plate)
};

/// The coupled run with the given skin model; means over [t_average, t_end].
PlateRun3d run_plate_3d(const ReducedBodyData& data, sph::WallModel model, double t_average,
                        double t_end)
{
  sph::CaseDescription<3> c;
  c.fluid.particle_spacing = 0.004;
  c.fluid.reference_density = rho;
  c.fluid.gravity = V3(0, 0, -g);
  c.fluid.scheme = sph::TimeScheme::symplectic;
  c.sound_coefficient = 20;
  c.tank.min = V3(0, 0, 0);
  c.tank.max = V3(0.14, width, 0.12);
  c.fluid_blocks.push_back({V3(0, 0, 0), V3(wall_x, width, depth)});
  auto fluid = sph::build_fluid(c);

  mbs::FloatingFrameOptions options;
  options.damping = mbs::DampingKind::modal;
  options.modal_damping_ratio = 0.7;
  auto system = std::make_unique<mbs::MultibodySystem<3>>(mbs::IntegratorOptions{});
  system->set_gravity(c.fluid.gravity);
  auto flexible = std::make_unique<mbs::FloatingFrameBody<3>>(data, options);
  const std::vector<int> tip = flexible->node_set("tip");
  flexible->set_pose(V3(wall_x, 0, 0), Eigen::Matrix3d::Identity());
  flexible->clamp_to_ground();
  auto* skin_body = flexible.get();
  system->add_body(std::move(flexible));
  auto plate = std::make_unique<coupling::MultibodyCoupledBody<3>>(
      "flexible", std::move(system), *skin_body, 0,
      [tip](const mbs::MultibodySystem<3>& s)
      {
        V3 sum = V3::Zero();
        for (int n : tip)
          sum += s.body(0).node_position(n);
        return V3(sum / double(tip.size()));
      });
  const V3 tip0 = plate->probe_position();

  coupling::CoSimulation<3> cosim(*fluid);
  const int index = cosim.add_body(*plate, "plate", model);
  if (model == sph::WallModel::dummy_particles)
  {
    const auto& surface = cosim.skin_wall(index).surface();
    const auto points = sph::generate_dummy_particles(surface, 0.004, 4);
    int wet = 0, inside = 0, dry = 0;
    for (const auto& x : points)
      (x.x() < wall_x ? wet : x.x() > wall_x + thickness ? dry : inside)++;
    std::printf("plate3d dummy points: %d in the water side, %d inside, %d on the dry side\n", wet,
                inside, dry);
    std::fflush(stdout);
  }
  std::vector<V3> skin_x;
  const auto start = std::chrono::steady_clock::now();
  PlateRun3d mean;
  double weight = 0, next_print = 0;
  while (cosim.time() < t_end)
  {
    const double dt = cosim.step();
    const auto& f = cosim.skin_wall(index).delivered();
    skin_body->skin_positions(skin_x);
    double fx = 0, mz = 0;
    for (std::size_t i = 0; i < f.size(); ++i)
    {
      fx += f[i].x();
      mz += f[i].x() * skin_x[i].z();
    }
    const double u = (plate->probe_position() - tip0).x();
    if (cosim.time() >= next_print)
    {
      std::printf("plate3d t %.3f Fx %.4f N  M %.5f N m  tip %.4e m  steps %ld  clock %.1f s\n",
                  cosim.time(), fx, mz, u, long(cosim.fluid().step_count()),
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      next_print += 0.02;
      std::fflush(stdout);
    }
    if (cosim.time() >= t_average)
    {
      mean.tip += dt * u;
      mean.force += dt * fx;
      mean.moment += dt * mz;
      weight += dt;
    }
  }
  mean.tip /= weight;
  mean.force /= weight;
  mean.moment /= weight;
  for (std::size_t i = fluid->n_boundary(); i < fluid->n_particles(); ++i)
    mean.dry += fluid->position(i).x() > wall_x + 0.02;
  return mean;
}

/// The 3D plate under the column: the reduced FE static tip (between the narrow beam and
/// the wide plate), and the coupled run's mean tip over [0.15, 0.3] s within 5 % of it.
/// Means over [0.15, 0.3] s: the first mode (27 Hz, zeta 0.7) has settled by 0.15 s.
void check_plate_3d(const PlateSpec& spec)
{
  const std::string file = plate_body_file_3d(spec);
  const ReducedBodyData data = read_reduced_body(file);
  const double reference = static_tip_displacement_3d(data);
  const fem::Material& material = spec.material;
  const double i_beam = width * std::pow(spec.thickness, 3) / 12;
  const double q0 = rho * g * depth * width;
  const double shape = std::pow(depth, 4) / 30 + std::pow(depth, 3) * (length - depth) / 24;
  const double beam = q0 * shape / (material.youngs_modulus * i_beam);
  const double plate_limit = beam * (1 - std::pow(material.poisson_ratio, 2));
  INFO("static tip: reduced 3D FE " << reference << " m, beam " << beam << " m, wide plate "
                                    << plate_limit << " m");
  REQUIRE(reference > 0.97 * plate_limit);
  REQUIRE(reference < 1.03 * beam);
  const double force = rho * g * depth * depth * width / 2, moment = force * depth / 3;

  const PlateRun3d run = run_plate_3d(data, spec.model, 0.15, 0.3);
  std::printf("%s 3d: tip %.4e m (FE %.4e, %+.2f %%), Fx %.4f N (%.4f), M %.5f N m (%.5f), "
              "dry %zu\n",
              spec.name.c_str(), run.tip, reference, 100 * (run.tip / reference - 1), run.force,
              force, run.moment, moment, run.dry);
  INFO("coupled tip displacement " << run.tip << " m, static FE " << reference << " m");
  CHECK(run.tip == Approx(reference).epsilon(0.05));
  CHECK(run.dry == 0);
}
} // namespace

// The thick plate as dummy particles (the Lennard-Jones skin measured -20 %, docs/bodies.md).
TEST_CASE("a clamped 3D plate under a water column deflects as the FE static solution",
          "[coupling]")
{
  check_plate_3d({thickness, stiff_plate(), sph::WallModel::dummy_particles, "plate_under_column"});
}

// The thin steel flap (0.5 mm = dp/8 at dp 4 mm) as a thin skin.
TEST_CASE("a thin 3D steel flap under a water column deflects as the FE static solution",
          "[coupling]")
{
  check_plate_3d(steel_flap);
}
