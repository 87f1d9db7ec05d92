// The geometrically nonlinear FE model (fem/nonlinear_elastic_body.h) against the elastica
// of a cantilever under a dead transverse tip load (closed form in elliptic integrals,
// checked here against Mattiasson 1981's table), in 2D and 3D, with St Venant-Kirchhoff and
// neo-Hooke; its dynamics against energy conservation and the linear modal frequency.
#include "fem/eigen_solver.h"
#include "fem/gmsh_reader.h"
#include "fem/nonlinear_elastic_body.h"
#include "fem_test_support.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace chipflex;
using namespace chipflex::fem;
using namespace chipflex::fem::testing;

namespace
{
/// Tip of an inextensible Euler-Bernoulli cantilever of length 1 under a dead transverse
/// tip load P with k = P L^2 / EI: {u/L, w/L}, the shortening along the undeformed axis and
/// the deflection across it. With the tip angle theta_L, k_m^2 = (1 + sin theta_L)/2 and
/// sin phi_1 = 1 / (k_m sqrt 2), the equilibrium EI theta'' = -P cos theta gives
///   sqrt(k) = K(k_m) - F(phi_1, k_m),
///   w sqrt(k) = sqrt(k) - 2 (E(k_m) - E(phi_1, k_m)),   (1 - u) sqrt(k) = sqrt(2 (2 k_m^2 - 1))
/// (Bisshopp & Drucker 1945; Mattiasson 1981, whose Table 1 these reproduce).
std::pair<double, double> elastica_tip(double k)
{
  auto length = [](double km) // sqrt(P/EI) L as a function of the modulus
  {
    const double phi1 = std::asin(1 / (km * std::sqrt(2.)));
    return std::comp_ellint_1(km) - std::ellint_1(km, phi1);
  };
  double lo = 1 / std::sqrt(2.) + 1e-15, hi = 1 - 1e-15;
  for (int i = 0; i < 200; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    (length(mid) < std::sqrt(k) ? lo : hi) = mid;
  }
  const double km = 0.5 * (lo + hi), phi1 = std::asin(1 / (km * std::sqrt(2.)));
  const double w = 1 - 2 * (std::comp_ellint_2(km) - std::ellint_2(km, phi1)) / std::sqrt(k);
  const double u = 1 - std::sqrt(2 * (2 * km * km - 1)) / std::sqrt(k);
  return {u, w};
}

Material beam_material()
{
  Material m;
  m.youngs_modulus = 1e7;
  m.poisson_ratio = 0; // EI = E I exactly, plane strain = plane stress
  m.density = 1000;
  return m;
}

/// Mean displacement of the tip group's nodes (node-ordered u).
Eigen::VectorXd tip_mean(const ElasticBody<2>& body, const Eigen::VectorXd& u, int dim = 2)
{
  const auto& tip = body.node_sets.at("tip");
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(dim);
  for (int n : tip)
    for (int d = 0; d < dim; ++d)
      mean[d] += u[n * dim + d] / tip.size();
  return mean;
}
} // namespace

TEST_CASE("elastica reference reproduces Mattiasson's table", "[fem][nonlinear]")
{
  // Mattiasson (1981), Table 1: P L^2/EI -> u/L, w/L. (u/L at P L^2/EI = 1 is 0.05643 there;
  // the closed form gives 0.056433.)
  const double table[][3] = {
      {1, 0.05643, 0.30172}, {2, 0.16064, 0.49346}, {5, 0.38763, 0.71379}, {10, 0.55500, 0.81061}};
  for (const auto& row : table)
  {
    const auto [u, w] = elastica_tip(row[0]);
    INFO("k = " << row[0] << ": u/L " << u << ", w/L " << w);
    CHECK(u == Approx(row[1]).margin(2e-5));
    CHECK(w == Approx(row[2]).margin(2e-5));
  }
}

TEST_CASE("2D cantilever under a dead tip load follows the elastica within 1 %", "[fem][nonlinear]")
{
  // L = 1 m, h = 0.01 m (slender: shear and stretching change the tip by ~1e-4), one
  // quadratic element through the thickness, 100 along.
  const double length = 1, h = 0.01;
  const GmshMeshData mesh = read_gmsh_mesh(gate_mesh(0.01, false, 0, length, h));
  const Material material = beam_material();
  const double ei = material.youngs_modulus * h * h * h / 12;
  for (const auto model : {HyperelasticModel::st_venant_kirchhoff, HyperelasticModel::neo_hooke})
  {
    NonlinearElasticBody<2> body(mesh, material, model, 2, "clamp", MPI_COMM_WORLD);
    for (const double k : {1., 2., 5., 10.})
    {
      const double p = k * ei / (length * length);
      // The beam hangs along -y from its clamp at y = L: the load along +x deflects it (w),
      // the tip rises towards the clamp (u).
      const LoadCase load = LoadCase::parse("force:tip:" + std::to_string(p) + ",0", 2, "test");
      StaticSolveStatistics statistics;
      const Eigen::VectorXd u = body.solve_static(load, 10, &statistics);
      const Eigen::VectorXd tip = tip_mean(body.body(), u);
      const auto [u_ref, w_ref] = elastica_tip(k);
      INFO(hyperelastic_model_name(model)
           << ", PL^2/EI = " << k << ": w/L " << tip[0] << " (elastica " << w_ref << "), u/L "
           << tip[1] << " (" << u_ref << "); " << statistics.increments << " increments, "
           << statistics.newton_iterations << " Newton iterations");
      CHECK(tip[0] == Approx(w_ref).epsilon(0.01));
      CHECK(tip[1] == Approx(u_ref).epsilon(0.01));
      // Newton with the consistent tangent: a few iterations per increment.
      CHECK(statistics.newton_iterations <= 10 * statistics.increments);
    }
  }
}

TEST_CASE("3D cantilever under a dead tip load follows the elastica within 1 %", "[fem][nonlinear]")
{
  // A square 0.02 x 0.02 m bar of length 1 m along x, clamped at x = 0, loaded along z.
  const double length = 1, b = 0.02;
  const GmshMeshData mesh = read_gmsh_mesh(strip_mesh(length, b, b, 0.02));
  const Material material = beam_material();
  const double ei = material.youngs_modulus * b * b * b * b / 12;
  NonlinearElasticBody<3> body(mesh, material, HyperelasticModel::st_venant_kirchhoff, 2, "clamp",
                               MPI_COMM_WORLD);
  const double k = 5;
  const LoadCase load =
      LoadCase::parse("force:tip:0,0," + std::to_string(k * ei / (length * length)), 3, "test");
  const Eigen::VectorXd u = body.solve_static(load, 10);
  const auto& tip = body.body().node_sets.at("tip");
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int n : tip)
    for (int d = 0; d < 3; ++d)
      mean[d] += u[n * 3 + d] / tip.size();
  const auto [u_ref, w_ref] = elastica_tip(k);
  INFO("3D, PL^2/EI = 5: w/L " << mean[2] << " (elastica " << w_ref << "), u/L " << -mean[0] << " ("
                               << u_ref << "), across " << mean[1]);
  CHECK(mean[2] == Approx(w_ref).epsilon(0.01));
  CHECK(-mean[0] == Approx(u_ref).epsilon(0.01));
  CHECK(std::abs(mean[1]) < 1e-8);
}

namespace
{
/// Dynamics of the 2D beam (L = 1 m, h = 0.01 m, 50 elements) released at rest from
/// `start` (node-ordered displacement), no load, trapezoidal rule (rho_infinity = 1),
/// undamped. Returns the tip's x displacement and the total energy (kinetic + strain) at
/// every step.
struct FreeVibration
{
  std::vector<double> time, tip_x, energy;
};

struct Beam
{
  Beam()
      : mesh(read_gmsh_mesh(gate_mesh(0.02, false, 0, 1.0, 0.01))),
        body(mesh, beam_material(), HyperelasticModel::st_venant_kirchhoff, 2, "clamp",
             MPI_COMM_WORLD)
  {
  }
  const double ei = beam_material().youngs_modulus * 1e-6 / 12;
  GmshMeshData mesh;
  NonlinearElasticBody<2> body;
};

FreeVibration free_vibration(NonlinearElasticBody<2>& body,
                             const NonlinearElasticBody<2>::DofVector& start, double dt, int n)
{
  const auto& b = body.body();
  auto zero = b.new_vector();
  zero = 0;
  body.start_dynamics({}, start, zero, zero);
  FreeVibration result;
  for (int s = 0; s <= n; ++s)
  {
    if (s > 0)
      body.step(dt, zero);
    result.time.push_back(s * dt);
    result.tip_x.push_back(tip_mean(b, b.to_nodal(body.displacement()))[0]);
    result.energy.push_back(body.kinetic_energy() + body.strain_energy(body.displacement()));
  }
  return result;
}
} // namespace

TEST_CASE("nonlinear free vibration: energy conserved by the trapezoidal rule", "[fem][nonlinear]")
{
  // Released from the PL^2/EI = 2 shape (tip deflection 0.49 L, far into the nonlinear
  // range), 400 steps per linear period (Euler-Bernoulli, 6.19 s), two periods: the largest
  // drift of kinetic + strain energy is 1.4e-4 (measured; 7.6e-5 from PL^2/EI = 1). The
  // trapezoidal rule conserves energy only to O(dt^2) on a nonlinear body and is not
  // unconditionally stable there (Simo & Tarnow 1992): at 100 steps per period the same
  // swing gains energy until Newton fails (PL^2/EI = 1: drift 2.4e-3, 0.5: 3.7e-4).
  Beam beam;
  const auto& b = beam.body.body();
  const auto start = beam.body.solve_static(
      b.load_vector(LoadCase::parse("force:tip:" + std::to_string(2 * beam.ei) + ",0", 2, "test")),
      10);
  const double period = 2 * M_PI / (1.8751 * 1.8751 * std::sqrt(beam.ei / (1000 * 0.01)));
  const auto r = free_vibration(beam.body, start, period / 400, 800);
  double drift = 0;
  for (double e : r.energy)
    drift = std::max(drift, std::abs(e - r.energy[0]) / r.energy[0]);
  double smallest = 0;
  for (double x : r.tip_x)
    smallest = std::min(smallest, x);
  INFO("initial energy " << r.energy[0] << " J/m, largest relative drift " << drift
                         << ", tip swings to " << smallest << " m");
  CHECK(drift < 1e-3);
  // It really swings through: to the other side, about as far (energy is conserved).
  CHECK(smallest < -0.4);
}

TEST_CASE("small-amplitude free vibration at the linear modal frequency", "[fem][nonlinear]")
{
  // Released from the first linear mode (FE eigenvector of K0, M) at a tip amplitude of
  // 1e-4 L: the nonlinear model must swing at that mode's frequency.
  Beam beam;
  const auto& b = beam.body.body();
  const auto modes = solve_eigenproblem(b.stiffness_matrix, b.mass_matrix, 1, 0, b.new_vector(),
                                        b.node_block_size);
  const double omega = std::sqrt(modes.eigenvalues[0]);
  auto start = modes.vectors[0];
  start *= 1e-4 / tip_mean(b, b.to_nodal(start))[0];
  const int steps_per_period = 60;
  const double period_linear = 2 * M_PI / omega;
  const auto r = free_vibration(beam.body, start, period_linear / steps_per_period,
                                int(2.1 * steps_per_period));
  std::vector<double> crossings;
  for (std::size_t s = 1; s < r.time.size(); ++s)
    if ((r.tip_x[s - 1] > 0) != (r.tip_x[s] > 0))
      crossings.push_back(r.time[s - 1] + (r.time[s] - r.time[s - 1]) * r.tip_x[s - 1] /
                                              (r.tip_x[s - 1] - r.tip_x[s]));
  REQUIRE(crossings.size() >= 4);
  const double period = 2 * (crossings.back() - crossings.front()) / (crossings.size() - 1);
  // The trapezoidal rule lengthens a period: omega' dt = 2 atan(omega dt / 2) (Hughes,
  // The Finite Element Method, 1987, section 9.3).
  const double w_dt = 2 * M_PI / steps_per_period;
  const double expected = period_linear * w_dt / (2 * std::atan(w_dt / 2));
  // And the linear mode is the Euler-Bernoulli one: 1.8751^2 sqrt(EI / (rho A L^4)).
  const double omega_eb = 1.8751 * 1.8751 * std::sqrt(beam.ei / (1000 * 0.01));
  INFO("period " << period << " s, linear FE mode " << period_linear << " s (Euler-Bernoulli "
                 << 2 * M_PI / omega_eb << " s), with the rule's elongation " << expected << " s");
  CHECK(period == Approx(expected).epsilon(1e-4));
  CHECK(omega == Approx(omega_eb).epsilon(0.005));
}

TEST_CASE("a load at rounding level: Newton converges to the linear answer", "[fem][nonlinear]")
{
  // A weightless body's first load in a coupled run can be 1e-13 N (the fluid barely
  // touching it): the displacement gradients are then 1e-16 and I + grad u would round
  // them away. The strain is formed from grad u alone, so the step converges and its
  // answer is the linear one (u proportional to the load).
  const Beam beam; // its mesh
  for (const auto model : {HyperelasticModel::st_venant_kirchhoff, HyperelasticModel::neo_hooke})
  {
    NonlinearElasticBody<2> body(beam.mesh, beam_material(), model, 2, "clamp", MPI_COMM_WORLD);
    const auto& b = body.body();
    auto zero = b.new_vector(), tiny = b.new_vector(), small = b.new_vector();
    zero = 0;
    tiny = b.load_vector(LoadCase::parse("force:tip:1e-13,0", 2, "test"));
    small = b.load_vector(LoadCase::parse("force:tip:1e-3,0", 2, "test"));
    // The static answers: at 1e-13 N, 1e-10 times the one at 1e-3 N.
    const double w_tiny = tip_mean(b, b.to_nodal(body.solve_static(tiny, 1)))[0];
    const double w_small = tip_mean(b, b.to_nodal(body.solve_static(small, 1)))[0];
    INFO(hyperelastic_model_name(model)
         << ": tip " << w_tiny << " m at 1e-13 N, " << w_small << " m at 1e-3 N");
    CHECK(w_tiny / w_small == Approx(1e-10).epsilon(1e-6));
    // One damped dynamic step from rest under the tiny load (the coupled gate's first step).
    NonlinearElasticBody<2>::DynamicsOptions options;
    options.rho_infinity = 0.9;
    options.rayleigh_stiffness = 3e-5;
    body.start_dynamics(options, zero, zero, zero);
    unsigned int iterations = 0;
    REQUIRE_NOTHROW(iterations = body.step(2e-4, tiny));
    CHECK(iterations <= 3);
  }
}
