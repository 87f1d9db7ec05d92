// The body FMU seen from an importer: `chipflex export fmu`'s library function writes the
// FMU, the test's own importer (fmu_loader.h) unpacks it, dlopens the library and runs the
// FMI 2.0 co-simulation calling sequence (instantiate, setup, initialisation, doStep,
// get/set, terminate, free) with two instances at once. References:
//  * chipflex's own mbs::FloatingFrameBody in an mbs::MultibodySystem, loaded and stepped
//    as `chipflex simulate` does: equal to 1e-9 relative at equal steps (same equations,
//    same integrator; only the order of floating-point sums may differ);
//  * the exact modal superposition of the undamped clamped step response (trapezoidal
//    rule, rho_inf = 1, phase error (w h)^2 / 12 per radian): 1e-3 of the peak;
//  * roll-back with fmi2Get/SetFMUstate (and through serialisation) repeats the same
//    steps bit for bit;
//  * bad input gives FMI status codes and a logged message, never a crash.

#include "common/reduced_body_file.h"
#include "coupling/fmu_body.h"
#include "coupling/multibody_coupled_body.h"
#include "fmu/fmu_export.h"
#include "fmu_loader.h"
#include "mbs/multibody_system.h"
#include "truss_beam.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace chipflex;
using chipflex::test::LoadedFmu;
using chipflex::test::logged;
using chipflex::test::test_callbacks;

namespace
{
struct TempFolder
{
  std::string path;
  TempFolder()
  {
    char name[] = "/tmp/chipflex_fmu_XXXXXX";
    path = mkdtemp(name);
  }
  ~TempFolder() { std::filesystem::remove_all(path); }
};

/// Writes the body file and exports it as an FMU; returns the FMU's path.
std::string export_body(const ReducedBodyData& body, const std::string& folder)
{
  write_reduced_body(folder + "/body.h5", body);
  fmu::FmuExportOptions options;
  options.runtime_library = CHIPFLEX_FMI_LIBRARY;
  fmu::export_fmu(folder + "/body.h5", folder + "/body.fmu", options);
  return folder + "/body.fmu";
}

fmi2Component instantiate(const LoadedFmu& f, const char* name)
{
  return f.fmi().Instantiate(name, fmi2CoSimulation, f.guid().c_str(), f.resource_uri().c_str(),
                             &test_callbacks(), fmi2False, fmi2False);
}

double get(const LoadedFmu& f, fmi2Component c, const std::string& name)
{
  const fmi2ValueReference vr = f.vr(name);
  double v = NAN;
  REQUIRE(f.fmi().GetReal(c, &vr, 1, &v) == fmi2OK);
  return v;
}

void set(const LoadedFmu& f, fmi2Component c, const std::string& name, double value)
{
  const fmi2ValueReference vr = f.vr(name);
  REQUIRE(f.fmi().SetReal(c, &vr, 1, &value) == fmi2OK);
}

/// Modal coordinates and skin positions, the outputs compared against the reference.
std::vector<double> outputs(const LoadedFmu& f, fmi2Component c, int n_modes, int n_skin, int dim)
{
  std::vector<fmi2ValueReference> vrs;
  const char* axis[] = {"x", "y", "z"};
  for (int k = 0; k < n_modes; ++k)
    vrs.push_back(f.vr("q[" + std::to_string(k) + "]"));
  for (int d = 0; d < dim; ++d)
    vrs.push_back(f.vr(std::string("frame.position.") + axis[d]));
  for (int i = 0; i < n_skin; ++i)
    for (int d = 0; d < dim; ++d)
      vrs.push_back(f.vr("skin.position[" + std::to_string(i) + "]." + axis[d]));
  std::vector<double> v(vrs.size());
  REQUIRE(f.fmi().GetReal(c, vrs.data(), vrs.size(), v.data()) == fmi2OK);
  return v;
}

template <int dim>
std::vector<double> reference_outputs(const mbs::FloatingFrameBody<dim>& b)
{
  std::vector<double> v(b.modal_coordinates().data(), b.modal_coordinates().data() + b.n_modes());
  for (int d = 0; d < dim; ++d)
    v.push_back(b.position()(d));
  for (int node : b.skin_node_ids())
    for (int d = 0; d < dim; ++d)
      v.push_back(b.node_position(node)(d));
  return v;
}

double max_abs(const std::vector<double>& v)
{
  double m = 0;
  for (double x : v)
    m = std::max(m, std::abs(x));
  return m;
}

double max_diff(const std::vector<double>& a, const std::vector<double>& b)
{
  double m = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    m = std::max(m, std::abs(a[k] - b[k]));
  return m;
}

/// Step-load response of the FMU against the in-process body, `steps` communication steps
/// of 2 internal steps each; returns the largest difference relative to the largest
/// displacement of the modal coordinates and skin (positions minus their start).
template <int dim>
double compare_with_own_body(const ReducedBodyData& body, bool clamped, double h, int steps,
                             const std::string& folder)
{
  const LoadedFmu f(export_body(body, folder), folder + "/unpacked");
  fmi2Component c = instantiate(f, "body");
  REQUIRE(c);
  REQUIRE(f.fmi().SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0) == fmi2OK);
  const fmi2ValueReference clamped_vr = f.vr("clamped");
  const fmi2Boolean clamped_value = clamped ? fmi2True : fmi2False;
  REQUIRE(f.fmi().SetBoolean(c, &clamped_vr, 1, &clamped_value) == fmi2OK);
  set(f, c, "step_size", h);
  REQUIRE(f.fmi().EnterInitializationMode(c) == fmi2OK);
  const Eigen::Matrix<double, dim, 1> total = Eigen::Matrix<double, dim, 1>::UnitY() * -0.7;
  const char* axis[] = {"x", "y", "z"};
  for (int d = 0; d < dim; ++d)
    set(f, c, std::string("set.tip.force.") + axis[d], total(d));
  REQUIRE(f.fmi().ExitInitializationMode(c) == fmi2OK);

  // The reference, as `chipflex simulate --load force:tip:0,-0.7 [--clamped]` runs it.
  mbs::MultibodySystem<dim> system;
  system.add_body(std::make_unique<mbs::FloatingFrameBody<dim>>(body));
  auto& b = system.body(0);
  if (clamped)
    b.clamp_to_ground();
  const auto& tip = b.node_set("tip");
  const std::vector<Eigen::Matrix<double, dim, 1>> shares(tip.size(), total / double(tip.size()));

  const int n_modes = body.n_modes(), n_skin = static_cast<int>(body.skin_nodes.size());
  const std::vector<double> start = reference_outputs(b);
  double diff = 0, scale = 0;
  for (int s = 0; s < steps; ++s)
  {
    REQUIRE(f.fmi().DoStep(c, s * 2 * h, 2 * h, fmi2True) == fmi2OK);
    for (int k = 0; k < 2; ++k)
    {
      b.set_node_forces(tip, shares);
      system.step(h);
    }
    const auto ref = reference_outputs(b), got = outputs(f, c, n_modes, n_skin, dim);
    REQUIRE(got.size() == ref.size());
    std::vector<double> moved(ref.size());
    for (std::size_t k = 0; k < ref.size(); ++k)
      moved[k] = ref[k] - start[k];
    diff = std::max(diff, max_diff(got, ref));
    scale = std::max(scale, max_abs(moved));
  }
  double t = -1;
  REQUIRE(f.fmi().GetRealStatus(c, fmi2LastSuccessfulTime, &t) == fmi2OK);
  CHECK(t == Approx(steps * 2 * h).epsilon(1e-12));
  REQUIRE(f.fmi().Terminate(c) == fmi2OK);
  f.fmi().FreeInstance(c);
  REQUIRE(scale > 0);
  return diff / scale;
}
} // namespace

TEST_CASE("The FMU's step-load response equals chipflex's own body at equal steps", "[fmu][import]")
{
  TempFolder tmp;
  mbs::test::TrussBeamSpec spec;
  spec.n_cells = 10;
  spec.n_modes = 4;
  SECTION("2D clamped")
  {
    const double rel =
        compare_with_own_body<2>(mbs::test::make_truss_beam(spec).body, true, 2e-5, 100, tmp.path);
    WARN("relative difference " << rel);
    CHECK(rel <= 1e-9);
  }
  SECTION("2D free-floating")
  {
    spec.clamped = false;
    const double rel =
        compare_with_own_body<2>(mbs::test::make_truss_beam(spec).body, false, 2e-5, 100, tmp.path);
    WARN("relative difference " << rel);
    CHECK(rel <= 1e-9);
  }
  SECTION("3D free-floating")
  {
    spec.dim = 3;
    spec.n_cells = 6;
    spec.clamped = false;
    const double rel =
        compare_with_own_body<3>(mbs::test::make_truss_beam(spec).body, false, 2e-5, 50, tmp.path);
    WARN("relative difference " << rel);
    CHECK(rel <= 1e-9);
  }
}

TEST_CASE("Two FMU instances at once: a clamped step response against modal superposition, "
          "roll-back by FMU state",
          "[fmu][import]")
{
  TempFolder tmp;
  mbs::test::TrussBeamSpec spec;
  spec.n_cells = 10;
  spec.n_modes = 3;
  const auto beam = mbs::test::make_truss_beam(spec);
  const LoadedFmu f(export_body(beam.body, tmp.path), tmp.path + "/unpacked");
  CHECK(std::string(f.fmi().GetVersion()) == "2.0");
  CHECK(std::string(f.fmi().GetTypesPlatform()) == "default");

  // Instance a: tip load (0, -0.5) on each of the tip's nodes, i.e. 0.5 n_tip in total;
  // instance b: twice that load, interleaved with a. Linear body: b = 2 a exactly.
  const auto& tip = beam.body.node_sets.at("tip");
  const double per_node = -0.5, n_tip = double(tip.size());
  fmi2Component a = instantiate(f, "a"), b = instantiate(f, "b");
  REQUIRE(a);
  REQUIRE(b);
  const auto& psi = beam.body.psi;
  const int m = beam.body.n_modes();
  Eigen::VectorXd p = Eigen::VectorXd::Zero(m), w2(m);
  for (int node : tip)
    p += psi.middleRows(2 * node, 2).transpose() * Eigen::Vector2d(0, per_node);
  for (int k = 0; k < m; ++k)
    w2(k) = beam.body.stiffness_matrix(k, k);
  const double period1 = 2 * M_PI / std::sqrt(w2(0)), period_m = 2 * M_PI / std::sqrt(w2(m - 1));
  const double h = period_m / 400;
  for (auto [c, factor] : {std::pair{a, 1.0}, std::pair{b, 2.0}})
  {
    REQUIRE(f.fmi().SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0) == fmi2OK);
    set(f, c, "rho_infinity", 1);
    set(f, c, "step_size", h);
    REQUIRE(f.fmi().EnterInitializationMode(c) == fmi2OK);
    set(f, c, "set.tip.force.y", factor * per_node * n_tip);
    REQUIRE(f.fmi().ExitInitializationMode(c) == fmi2OK);
  }
  const int steps = static_cast<int>(2 * period1 / h);
  const std::string probe = "q[0]";
  double max_err = 0, max_ref = 0, max_ratio_err = 0;
  fmi2FMUstate saved = nullptr;
  std::vector<double> after_save;
  const int save_at = steps / 2;
  for (int s = 0; s < steps; ++s)
  {
    if (s == save_at)
      REQUIRE(f.fmi().GetFMUstate(a, &saved) == fmi2OK);
    REQUIRE(f.fmi().DoStep(a, s * h, h, fmi2False) == fmi2OK);
    REQUIRE(f.fmi().DoStep(b, s * h, h, fmi2False) == fmi2OK);
    const double t = (s + 1) * h;
    for (int k = 0; k < m; ++k)
    {
      const double exact = p(k) / w2(k) * (1 - std::cos(std::sqrt(w2(k)) * t));
      const double qa = get(f, a, "q[" + std::to_string(k) + "]");
      max_err = std::max(max_err, std::abs(qa - exact));
      max_ref = std::max(max_ref, std::abs(exact));
      max_ratio_err =
          std::max(max_ratio_err, std::abs(get(f, b, "q[" + std::to_string(k) + "]") - 2 * qa));
    }
    if (s >= save_at)
      after_save.push_back(get(f, a, probe));
  }
  WARN("modal error " << max_err << " of " << max_ref << "; |q_b - 2 q_a| " << max_ratio_err);
  CHECK(max_err <= 1e-3 * max_ref);
  CHECK(max_ratio_err <= 1e-12 * max_ref);

  // Roll back instance a to the saved point and repeat: the same values bit for bit.
  REQUIRE(f.fmi().SetFMUstate(a, saved) == fmi2OK);
  for (int s = save_at; s < steps; ++s)
  {
    REQUIRE(f.fmi().DoStep(a, s * h, h, fmi2False) == fmi2OK);
    CHECK(get(f, a, probe) == after_save[s - save_at]);
  }
  // The same through serialisation, restored into instance b (built from the same FMU).
  std::size_t size = 0;
  REQUIRE(f.fmi().SerializedFMUstateSize(a, saved, &size) == fmi2OK);
  std::vector<fmi2Byte> bytes(size);
  REQUIRE(f.fmi().SerializeFMUstate(a, saved, bytes.data(), size) == fmi2OK);
  fmi2FMUstate copy = nullptr;
  REQUIRE(f.fmi().DeSerializeFMUstate(b, bytes.data(), size, &copy) == fmi2OK);
  REQUIRE(f.fmi().SetFMUstate(b, copy) == fmi2OK);
  REQUIRE(f.fmi().DoStep(b, save_at * h, h, fmi2False) == fmi2OK);
  CHECK(get(f, b, probe) == after_save[0]);
  // A truncated serialised state is refused.
  fmi2FMUstate bad = nullptr;
  logged().clear();
  CHECK(f.fmi().DeSerializeFMUstate(b, bytes.data(), size / 2, &bad) == fmi2Error);
  CHECK(!logged().empty());
  REQUIRE(f.fmi().FreeFMUstate(a, &saved) == fmi2OK);
  REQUIRE(f.fmi().FreeFMUstate(b, &copy) == fmi2OK);
  CHECK(saved == nullptr);

  // fmi2Reset: back to the start values, the whole sequence again.
  REQUIRE(f.fmi().Reset(a) == fmi2OK);
  REQUIRE(f.fmi().EnterInitializationMode(a) == fmi2OK);
  REQUIRE(f.fmi().ExitInitializationMode(a) == fmi2OK);
  CHECK(get(f, a, "q[0]") == 0);
  CHECK(get(f, a, "set.tip.force.y") == 0);
  f.fmi().Terminate(a);
  f.fmi().Terminate(b);
  f.fmi().FreeInstance(a);
  f.fmi().FreeInstance(b);
}

TEST_CASE("Bad input to the FMU gives FMI status codes and a logged message", "[fmu][import]")
{
  TempFolder tmp;
  mbs::test::TrussBeamSpec spec;
  spec.n_cells = 6;
  spec.n_modes = 2;
  spec.clamped = false;
  const auto beam = mbs::test::make_truss_beam(spec);
  const LoadedFmu f(export_body(beam.body, tmp.path), tmp.path + "/unpacked");
  const auto& fmi = f.fmi();
  const auto last_message = []
  { return logged().empty() ? std::string() : logged().back().message; };

  // What the exported model description promises, as an importer's XML parser reads it.
  const Fmi2ModelDescription& md = f.model_description();
  CHECK(md.fmi_version == "2.0");
  REQUIRE(md.co_simulation);
  CHECK(md.co_simulation->can_get_and_set_fmu_state);
  CHECK(md.co_simulation->can_serialize_fmu_state);
  CHECK(md.co_simulation->can_handle_variable_communication_step_size);
  REQUIRE(md.find("clamped"));
  CHECK(md.find("clamped")->type == "Boolean");
  CHECK(md.find("clamped")->causality == "parameter");
  CHECK(md.find("clamped")->variability == "fixed");
  REQUIRE(md.find("q[0]"));
  CHECK(md.find("q[0]")->causality == "output");
  CHECK_FALSE(md.find("q[0]")->start);

  // Instantiation: wrong GUID, model exchange, a resource folder with a broken body file.
  logged().clear();
  CHECK(fmi.Instantiate("x", fmi2CoSimulation, "{wrong}", f.resource_uri().c_str(),
                        &test_callbacks(), fmi2False, fmi2False) == nullptr);
  CHECK(last_message().find("GUID") != std::string::npos);
  CHECK(fmi.Instantiate("x", fmi2ModelExchange, f.guid().c_str(), f.resource_uri().c_str(),
                        &test_callbacks(), fmi2False, fmi2False) == nullptr);
  CHECK(last_message().find("co-simulation only") != std::string::npos);
  std::filesystem::create_directories(tmp.path + "/broken/resources");
  std::ofstream(tmp.path + "/broken/resources/body.h5") << "not an HDF5 file";
  logged().clear();
  CHECK(fmi.Instantiate("x", fmi2CoSimulation, f.guid().c_str(),
                        ("file://" + tmp.path + "/broken/resources").c_str(), &test_callbacks(),
                        fmi2False, fmi2False) == nullptr);
  CHECK(last_message().find("body.h5") != std::string::npos);
  CHECK(fmi.Instantiate("x", fmi2CoSimulation, f.guid().c_str(), "http://example.org/",
                        &test_callbacks(), fmi2False, fmi2False) == nullptr);

  fmi2Component c = instantiate(f, "c");
  REQUIRE(c);
  const fmi2ValueReference unknown = 1u << 30, output = f.vr("q[0]");
  const double one = 1, nan = NAN;
  logged().clear();
  CHECK(fmi.SetReal(c, &unknown, 1, &one) == fmi2Error);
  CHECK(last_message().find("value reference") != std::string::npos);
  CHECK(fmi.SetReal(c, &output, 1, &one) == fmi2Error);
  CHECK(last_message().find("is an output") != std::string::npos);
  const fmi2ValueReference force = f.vr("frame.force.x");
  CHECK(fmi.SetReal(c, &force, 1, &nan) == fmi2Error);
  CHECK(last_message().find("not finite") != std::string::npos);
  const fmi2ValueReference clamped = f.vr("clamped");
  CHECK(fmi.SetReal(c, &clamped, 1, &one) == fmi2Error); // a Boolean, not a Real
  double value = 0;
  CHECK(fmi.GetReal(c, &output, 1, &value) == fmi2Error); // no outputs before initialisation
  CHECK(fmi.DoStep(c, 0, 1e-3, fmi2True) == fmi2Error);   // not initialised
  CHECK(last_message().find("fmi2DoStep") != std::string::npos);

  // A step size the integrator cannot use is refused at the end of initialisation.
  set(f, c, "step_size", -1);
  REQUIRE(fmi.EnterInitializationMode(c) == fmi2OK);
  CHECK(fmi.ExitInitializationMode(c) == fmi2Error);
  CHECK(last_message().find("step_size") != std::string::npos);
  set(f, c, "step_size", 1e-4);
  REQUIRE(fmi.ExitInitializationMode(c) == fmi2OK);
  const fmi2ValueReference step_size = f.vr("step_size");
  CHECK(fmi.SetReal(c, &step_size, 1, &one) == fmi2Error); // fixed after initialisation
  CHECK(last_message().find("fixed") != std::string::npos);
  CHECK(fmi.DoStep(c, 0, -1e-3, fmi2True) == fmi2Error);
  CHECK(fmi.DoStep(c, 0, 0, fmi2True) == fmi2Error);
  CHECK(fmi.DoStep(c, 0.5, 1e-3, fmi2True) == fmi2Error); // not the FMU's time
  CHECK(last_message().find("not the FMU's time") != std::string::npos);

  // A step the integrator cannot take: a huge moment spins the free body so fast within
  // one long step that Newton's method fails; the FMU discards the step and stays at t.
  REQUIRE(fmi.DoStep(c, 0, 1e-3, fmi2True) == fmi2OK);
  const double q_before = get(f, c, "q[0]");
  set(f, c, "frame.moment", 1e9);
  logged().clear();
  const fmi2Status spun = fmi.DoStep(c, 1e-3, 10.0, fmi2True);
  CHECK(spun == fmi2Discard);
  CHECK(last_message().find("state stays at t") != std::string::npos);
  double t = -1;
  REQUIRE(fmi.GetRealStatus(c, fmi2LastSuccessfulTime, &t) == fmi2OK);
  CHECK(t == Approx(1e-3));
  CHECK(get(f, c, "q[0]") == q_before);
  set(f, c, "frame.moment", 0);
  CHECK(fmi.DoStep(c, 1e-3, 1e-3, fmi2True) == fmi2OK); // and it goes on
  REQUIRE(fmi.Terminate(c) == fmi2OK);
  CHECK(fmi.DoStep(c, 2e-3, 1e-3, fmi2True) == fmi2Error);
  fmi.FreeInstance(c);
  CHECK(fmi.DoStep(nullptr, 0, 1e-3, fmi2True) == fmi2Error);
}

TEST_CASE("The fmu body kind couples an FMU's skin like the flexible body, with checkpoints",
          "[fmu][coupling]")
{
  // The same truss body as a `flexible` and as an `fmu` coupled body: equal skin faces,
  // positions and velocities under the same skin forces (same body and integrator behind
  // the FMI calls: 1e-12 of the motion), and restore(state()) through
  // fmi2SerializeFMUstate repeats the steps exactly.
  TempFolder tmp;
  mbs::test::TrussBeamSpec spec;
  spec.n_cells = 8;
  spec.n_modes = 3;
  const auto beam = mbs::test::make_truss_beam(spec);
  coupling::FmuBodySettings d;
  d.name = "beam";
  d.position = Eigen::Vector2d(0.1, 0.2);
  d.angle = 0.3;
  d.fmu_file = export_body(beam.body, tmp.path);
  d.rayleigh_stiffness = 1e-4;
  d.max_step = 2e-5;
  const Eigen::Vector2d gravity(0, -9.81);
  // The flexible body as a case's `flexible` kind builds it: clamped, Rayleigh damping,
  // sub-steps of max_step, generalised alpha.
  mbs::FloatingFrameOptions options;
  options.damping = mbs::DampingKind::rayleigh;
  options.rayleigh_stiffness = d.rayleigh_stiffness;
  auto system = std::make_unique<mbs::MultibodySystem<2>>(mbs::IntegratorOptions{});
  system->set_gravity(gravity);
  auto body = std::make_unique<mbs::FloatingFrameBody<2>>(beam.body, options);
  body->set_pose(d.position, d.angle);
  body->clamp_to_ground();
  auto* skin = body.get();
  system->add_body(std::move(body));
  const std::vector<int> tip = skin->node_set("tip");
  std::unique_ptr<coupling::CoupledBody<2>> flexible =
      std::make_unique<coupling::MultibodyCoupledBody<2>>(
          "flexible", std::move(system), *skin, d.max_step,
          [tip](const mbs::MultibodySystem<2>& s)
          {
            Eigen::Vector2d sum = Eigen::Vector2d::Zero();
            for (int n : tip)
              sum += s.body(0).node_position(n);
            return Eigen::Vector2d(sum / double(tip.size()));
          });
  auto fmu_body = coupling::make_fmu_body(d, gravity);
  CHECK(fmu_body->kind() == "fmu");
  REQUIRE(fmu_body->skin().n_skin_nodes() == flexible->skin().n_skin_nodes());
  CHECK(fmu_body->skin().skin_faces() == flexible->skin().skin_faces());
  const std::size_t n = flexible->skin().n_skin_nodes();
  std::vector<Eigen::Vector2d> forces(n);
  for (std::size_t i = 0; i < n; ++i)
    forces[i] = Eigen::Vector2d(0.1 * std::sin(double(i)), -0.2);
  std::vector<Eigen::Vector2d> xa, xb, va, vb;
  double diff = 0, moved = 0;
  flexible->skin().skin_positions(xa);
  const auto start = xa;
  std::vector<double> saved;
  std::vector<Eigen::Vector2d> after_save;
  for (int s = 0; s < 40; ++s)
  {
    if (s == 20)
      saved = fmu_body->state();
    for (auto* b : {flexible.get(), fmu_body.get()})
    {
      b->skin().set_skin_forces(forces);
      b->advance(1e-4);
    }
    flexible->skin().skin_positions(xa);
    fmu_body->skin().skin_positions(xb);
    flexible->skin().skin_velocities(va);
    fmu_body->skin().skin_velocities(vb);
    for (std::size_t i = 0; i < n; ++i)
    {
      diff = std::max(diff, (xa[i] - xb[i]).norm());
      moved = std::max(moved, (xa[i] - start[i]).norm());
      diff = std::max(diff, 1e-4 * (va[i] - vb[i]).norm());
    }
    if (s == 39)
      after_save = xb;
  }
  WARN(
      "fmu vs flexible skin: " << diff << " m of " << moved << " m motion; probe "
                               << (fmu_body->probe_position() - flexible->probe_position()).norm());
  CHECK(moved > 1e-4);
  CHECK(diff <= 1e-12 * moved);
  CHECK((fmu_body->probe_position() - flexible->probe_position()).norm() <= 1e-12 * moved);
  CHECK((fmu_body->linear_momentum() - flexible->linear_momentum()).norm() <=
        1e-9 * flexible->linear_momentum().norm() + 1e-15);
  fmu_body->restore(saved);
  for (int s = 20; s < 40; ++s)
  {
    fmu_body->skin().set_skin_forces(forces);
    fmu_body->advance(1e-4);
  }
  fmu_body->skin().skin_positions(xb);
  for (std::size_t i = 0; i < n; ++i)
    CHECK(xb[i] == after_save[i]);
}
