// The geometrically nonlinear reduced body (reduce --nonlinear) against the elastica: a
// slender cantilever under a dead transverse tip load P up to P L^2 / EI = 10. The reference
// is the closed-form solution (Bisshopp & Drucker 1945; tabulated by Mattiasson 1981,
// IJNME 17), computed here by quadrature and checked against Mattiasson's table first.
// The reduced body's static equilibrium f(q) = Psi^T F is solved by Newton with the
// polynomial's tangent, in load steps.

#include "common/polynomial_stiffness.h"
#include "common/reduced_body_file.h"
#include "fem/gmsh_reader.h"
#include "fem/nonlinear_elastic_body.h"
#include "fem_test_support.h"
#include "meshes/chip_mesher.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace chipflex;
using namespace chipflex::fem;
using namespace chipflex::fem::testing;

namespace
{
/// Composite Simpson rule on [a, b].
template <class F>
double simpson(F&& f, double a, double b, int n = 2000)
{
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i)
    s += f(a + i * h) * (i % 2 ? 4 : 2);
  return s * h / 3;
}

/// Elastica of a cantilever under a dead tip load perpendicular to its axis, alpha =
/// P L^2 / EI: tip angle phi solves sqrt(alpha) = int_0^phi dtheta / sqrt(2 (sin phi -
/// sin theta)); then u / L = 1 - sqrt(2 sin phi / alpha) (axial shortening) and w / L =
/// int_0^phi sin theta dtheta / sqrt(2 (sin phi - sin theta)) / sqrt(alpha). With t =
/// sqrt(sin phi - sin theta) both integrands are smooth for phi < pi/2.
struct Elastica
{
  double angle, u, w;
};
Elastica elastica(double alpha)
{
  auto integrals = [](double phi)
  {
    const double s0 = std::sin(phi);
    auto cosine = [s0](double t) { return std::sqrt(1 - std::pow(s0 - t * t, 2)); };
    const double a = simpson([&](double t) { return M_SQRT2 / cosine(t); }, 0, std::sqrt(s0));
    const double b =
        simpson([&](double t) { return M_SQRT2 * (s0 - t * t) / cosine(t); }, 0, std::sqrt(s0));
    return std::make_pair(a, b);
  };
  double lo = 1e-12, hi = M_PI / 2 - 1e-9;
  for (int i = 0; i < 80; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    (integrals(mid).first < std::sqrt(alpha) ? lo : hi) = mid;
  }
  const auto [a, b] = integrals(lo);
  (void)a;
  return {lo, 1 - std::sqrt(2 * std::sin(lo) / alpha), b / std::sqrt(alpha)};
}

struct Beam
{
  double length = 1, thickness = 0.02, e = 1e7, nu = 0.3, rho = 1000;
  double ei() const { return e * std::pow(thickness, 3) / 12; } // plane stress, per metre

  Material material() const
  {
    Material m;
    m.youngs_modulus = e;
    m.poisson_ratio = nu;
    m.density = rho;
    m.plane_stress = true;
    return m;
  }
  /// The 2D cantilever (two elements through the thickness), clamped at x = 0.
  std::string write_mesh(const std::string& name) const
  {
    meshes::BlockMeshSpec spec;
    spec.dim = 2;
    spec.extent = {length, thickness, 0};
    spec.long_axis = 0;
    spec.clamp_at_max = false;
    spec.size = thickness / 2;
    const std::string mesh = scratch(name);
    meshes::write_block_mesh(spec, mesh);
    return mesh;
  }
  /// 4 modes + the static tip-load mode + the modal derivatives of the first 4 modes
  /// (10 pairs; deflation keeps 9).
  ReductionSettings nonlinear_reduction(const std::string& mesh) const
  {
    ReductionSettings s;
    s.mesh_file = mesh;
    s.clamp_group = "clamp";
    s.material = material();
    s.n_modes = 4;
    s.static_modes = {"force:tip:0,-1"};
    s.nonlinear = true;
    s.derivative_modes = 4;
    return s;
  }
};

/// Newton on the reduced static equilibrium f(q) = load with the polynomial's tangent,
/// from the q given (the previous load step's answer).
void solve_equilibrium(const PolynomialStiffness& svk, const Eigen::VectorXd& load,
                       Eigen::VectorXd& q)
{
  Eigen::VectorXd f(q.size());
  Eigen::MatrixXd kt;
  for (int it = 0;; ++it)
  {
    REQUIRE(it < 50);
    svk.evaluate(q, f, &kt);
    const Eigen::VectorXd dq = kt.ldlt().solve(load - f);
    q += dq;
    if (dq.norm() <= 1e-12 * q.norm())
      break;
  }
}

/// Static equilibrium of the reduced body under a dead tip force (0, -p) shared equally by
/// the tip nodes; returns the tip centre's displacement (x, y).
Eigen::Vector2d reduced_tip_displacement(const ReducedBodyData& body, const Beam& beam,
                                         const std::vector<double>& alphas,
                                         std::vector<Eigen::Vector2d>& out)
{
  const PolynomialStiffness svk(body.stiffness_matrix, body.quadratic_stiffness,
                                body.cubic_stiffness);
  const int m = body.n_modes();
  const auto& tip = body.node_sets.at("tip");
  Eigen::VectorXd unit_load = Eigen::VectorXd::Zero(m); // Psi^T F for P = 1
  int centre = tip[0];
  for (const int node : tip)
  {
    unit_load -= body.psi.row(2 * node + 1).transpose() / double(tip.size());
    if (std::abs(body.nodes(node, 1) - beam.thickness / 2) <
        std::abs(body.nodes(centre, 1) - beam.thickness / 2))
      centre = node;
  }
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m);
  double alpha = 0;
  out.clear();
  for (const double target : alphas)
  {
    while (alpha < target - 1e-12)
    {
      alpha = std::min(target, alpha + 0.25);
      const Eigen::VectorXd load = alpha * beam.ei() / std::pow(beam.length, 2) * unit_load;
      solve_equilibrium(svk, load, q);
    }
    out.push_back(body.psi.middleRows(2 * centre, 2) * q);
  }
  return out.back();
}
} // namespace

TEST_CASE("elastica by quadrature reproduces Mattiasson's table", "[fem][nonlinear]")
{
  // Mattiasson (1981), Table 1: P L^2/EI, u/L, w/L (u: shortening, w: deflection)
  const double table[4][3] = {
      {1, 0.05643, 0.30172}, {2, 0.16064, 0.49346}, {5, 0.38763, 0.71379}, {10, 0.55500, 0.81061}};
  for (const auto& row : table)
  {
    const auto e = elastica(row[0]);
    CHECK(e.u == Approx(row[1]).margin(2e-5));
    CHECK(e.w == Approx(row[2]).margin(2e-5));
  }
}

TEST_CASE("nonlinear reduced cantilever follows the elastica up to P L^2/EI = 10",
          "[fem][nonlinear]")
{
  const Beam beam;
  const ReductionSettings s = beam.nonlinear_reduction(beam.write_mesh("elastica_beam.msh"));
  const ReducedBodyData body = reduce_body(s);
  REQUIRE(body.nonlinear());
  CHECK(body.n_modal_derivatives >= 6);
  CHECK(body.mode_kinds.back().rfind("derivative:", 0) == 0);

  const std::vector<double> alphas{1, 2, 5, 10};
  std::vector<Eigen::Vector2d> tips;
  reduced_tip_displacement(body, beam, alphas, tips);
  for (std::size_t k = 0; k < alphas.size(); ++k)
  {
    const auto e = elastica(alphas[k]);
    const double u = -tips[k].x() / beam.length, w = -tips[k].y() / beam.length;
    // error of the tip position relative to the deflection
    const double error = std::hypot(u - e.u, w - e.w) / std::hypot(e.u, e.w);
    WARN("P L^2/EI = " << alphas[k] << ": reduced u/L " << u << " w/L " << w << ", elastica " << e.u
                       << " " << e.w << ", tip position error " << 100 * error << " %");
    // measured: 0.05 % at most (0.04 % with 8 modes and their 36 derivative pairs); the
    // linear body's tip would be off by 90 % at P L^2/EI = 1 already
    CHECK(error < 5e-3);
  }
}

TEST_CASE("nonlinear reduced 3D strip follows the elastica at P L^2/EI = 2", "[fem][nonlinear]")
{
  // nu = 0: no anticlastic curvature, so the strip bends with EI = E b h^3 / 12 exactly
  const double length = 1, width = 0.04, thickness = 0.02, e = 1e7;
  const std::string mesh = strip_mesh(length, width, thickness, 0.02);
  ReductionSettings s;
  s.mesh_file = mesh;
  s.clamp_group = "clamp";
  s.material.youngs_modulus = e;
  s.material.poisson_ratio = 0;
  s.material.density = 1000;
  s.n_modes = 4;
  s.static_modes = {"force:tip:0,0,-1"};
  s.nonlinear = true;
  s.derivative_modes = 4;
  const ReducedBodyData body = reduce_body(s);
  REQUIRE(body.nonlinear());
  const PolynomialStiffness svk(body.stiffness_matrix, body.quadratic_stiffness,
                                body.cubic_stiffness);
  const int m = body.n_modes();
  const auto& tip = body.node_sets.at("tip");
  Eigen::VectorXd unit_load = Eigen::VectorXd::Zero(m);
  int centre = tip[0];
  auto off_centre = [&](int node)
  { return std::hypot(body.nodes(node, 1) - width / 2, body.nodes(node, 2) - thickness / 2); };
  for (const int node : tip)
  {
    unit_load -= body.psi.row(3 * node + 2).transpose() / double(tip.size());
    if (off_centre(node) < off_centre(centre))
      centre = node;
  }
  const double ei = e * width * std::pow(thickness, 3) / 12, alpha = 2;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m);
  for (int step = 1; step <= 8; ++step)
  {
    const Eigen::VectorXd load = step / 8.0 * alpha * ei / (length * length) * unit_load;
    solve_equilibrium(svk, load, q);
  }
  const Eigen::Vector3d tip_u = body.psi.middleRows(3 * centre, 3) * q;
  const auto ref = elastica(alpha);
  const double u = -tip_u.x() / length, w = -tip_u.z() / length;
  const double error = std::hypot(u - ref.u, w - ref.w) / std::hypot(ref.u, ref.w);
  WARN("3D strip, " << m << " coordinates: u/L " << u << " w/L " << w << ", elastica " << ref.u
                    << " " << ref.w << ", tip position error " << 100 * error << " %");
  CHECK(std::abs(tip_u.y()) < 1e-6 * length); // symmetric: no sideways motion
  CHECK(error < 0.01);
}

TEST_CASE("nonlinear reduced cantilever against the full nonlinear FE model", "[fem][nonlinear]")
{
  // The same mesh, material (St Venant-Kirchhoff) and consistent dead tip load for both:
  // what differs is only the reduction (u = Psi q with 4 modes + 1 static + 9 derivatives).
  const Beam beam;
  const std::string mesh_file = beam.write_mesh("elastica_beam_full.msh");
  const Material material = beam.material();
  const ReductionSettings s = beam.nonlinear_reduction(mesh_file);
  const ReducedBodyData reduced = reduce_body(s);
  const PolynomialStiffness svk(reduced.stiffness_matrix, reduced.quadratic_stiffness,
                                reduced.cubic_stiffness);
  const int m = reduced.n_modes();

  const GmshMeshData mesh = read_gmsh_mesh(mesh_file);
  NonlinearElasticBody<2> full(mesh, material, HyperelasticModel::st_venant_kirchhoff, 2, "clamp",
                               MPI_COMM_WORLD);
  const auto& tip = reduced.node_sets.at("tip");
  int centre = tip[0];
  for (const int node : tip)
    if (std::abs(reduced.nodes(node, 1) - beam.thickness / 2) <
        std::abs(reduced.nodes(centre, 1) - beam.thickness / 2))
      centre = node;
  // the node order of both is the walk over the same cells: the same ids
  REQUIRE((full.body().node_coordinates[centre][0] - reduced.nodes(centre, 0)) ==
          Approx(0).margin(1e-12));
  const LoadCase unit = LoadCase::parse("force:tip:0,-1", 2, "test");
  const Eigen::VectorXd unit_modal =
      reduced.psi.transpose() * full.body().to_nodal(full.body().load_vector(unit));

  Eigen::VectorXd q = Eigen::VectorXd::Zero(m);
  double alpha = 0;
  for (const double target : {1., 2., 5., 10.})
  {
    const double p = target * beam.ei() / std::pow(beam.length, 2);
    while (alpha < target - 1e-12) // reduced: Newton in load steps of 0.25
    {
      alpha = std::min(target, alpha + 0.25);
      const Eigen::VectorXd load = alpha * beam.ei() / std::pow(beam.length, 2) * unit_modal;
      solve_equilibrium(svk, load, q);
    }
    const Eigen::Vector2d u_reduced = reduced.psi.middleRows(2 * centre, 2) * q;
    const Eigen::VectorXd u_full = full.solve_static(
        LoadCase::parse("force:tip:0," + std::to_string(-p), 2, "test"), 10 * unsigned(target));
    const Eigen::Vector2d tip_full = u_full.segment<2>(2 * centre);
    const double error = (u_reduced - tip_full).norm() / tip_full.norm();
    WARN("P L^2/EI = " << target << ": tip displacement reduced (" << u_reduced.transpose()
                       << "), full FE (" << tip_full.transpose() << "), difference " << 100 * error
                       << " %");
    CHECK(error < 0.02);
  }
}

TEST_CASE("nonlinear reduced helical chip against the full nonlinear FE model in 3D",
          "[fem][nonlinear][chip]")
{
  // A steel helical chip (one turn, curl radius 3 mm, pitch 2 mm, 2 x 0.5 mm section,
  // quadratic hexahedra on the curved geometry), clamped at its start face and pulled along
  // the helix axis at its end face by a dead load large enough that the linear answer is
  // off by more than 5 %. Reduced: 6 modes + the static mode of that load + the modal
  // derivatives of the first 5 modes, St Venant-Kirchhoff as the cubic polynomial; full: the
  // St Venant-Kirchhoff FE model of the same mesh. Both are compared at the end face's mean
  // displacement within 3 %.
  meshes::ChipMeshSpec spec;
  spec.shape = meshes::ChipMeshSpec::Shape::helical;
  spec.width = 2e-3;
  spec.thickness = 0.5e-3;
  spec.curl_radius = 3e-3;
  spec.pitch = 2e-3;
  spec.turns = 1;
  spec.size = 1e-3;
  const std::string mesh_file = scratch("helical_chip_nonlinear.msh");
  meshes::write_chip_mesh(spec, mesh_file);
  Material steel;
  steel.youngs_modulus = 2.1e11;
  steel.poisson_ratio = 0.3;
  steel.density = 7850;

  ReductionSettings s;
  s.mesh_file = mesh_file;
  s.clamp_group = "start";
  s.material = steel;
  s.n_modes = 6;
  s.static_modes = {"force:end:0,0,1"};
  s.nonlinear = true;
  s.derivative_modes = 5;
  const ReducedBodyData reduced = reduce_body(s);
  REQUIRE(reduced.nonlinear());
  const PolynomialStiffness svk(reduced.stiffness_matrix, reduced.quadratic_stiffness,
                                reduced.cubic_stiffness);
  const int m = reduced.n_modes();

  const GmshMeshData mesh = read_gmsh_mesh(mesh_file);
  NonlinearElasticBody<3> full(mesh, steel, HyperelasticModel::st_venant_kirchhoff, 2, "start",
                               MPI_COMM_WORLD);
  const auto& end = reduced.node_sets.at("end");
  const auto end_mean = [&](const Eigen::VectorXd& u)
  {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const int node : end)
      sum += u.segment<3>(3 * node);
    return Eigen::Vector3d(sum / double(end.size()));
  };
  const LoadCase unit = LoadCase::parse("force:end:0,0,1", 3, "test");
  const Eigen::VectorXd unit_modal =
      reduced.psi.transpose() * full.body().to_nodal(full.body().load_vector(unit));
  // The load whose linear answer moves the end by half the curl radius.
  const Eigen::VectorXd q_unit = reduced.stiffness_matrix.ldlt().solve(unit_modal);
  const double force = 0.5 * spec.curl_radius / end_mean(reduced.psi * q_unit).norm();
  const Eigen::Vector3d u_linear = force * end_mean(reduced.psi * q_unit);

  Eigen::VectorXd q = Eigen::VectorXd::Zero(m);
  for (int step = 1; step <= 20; ++step) // reduced: Newton in 20 load steps
  {
    const Eigen::VectorXd load = (force * step / 20) * unit_modal;
    solve_equilibrium(svk, load, q);
  }
  const Eigen::Vector3d u_reduced = end_mean(reduced.psi * q);
  const Eigen::Vector3d u_full = end_mean(
      full.solve_static(LoadCase::parse("force:end:0,0," + std::to_string(force), 3, "test"), 20));
  const double error = (u_reduced - u_full).norm() / u_full.norm();
  const double nonlinearity = (u_linear - u_full).norm() / u_full.norm();
  WARN("helical chip, end load " << force << " N (" << m << " reduced coordinates): end "
                                 << "displacement reduced (" << u_reduced.transpose()
                                 << "), full FE (" << u_full.transpose() << "), linear ("
                                 << u_linear.transpose() << "); reduced vs full " << 100 * error
                                 << " %, linear vs full " << 100 * nonlinearity << " %");
  CHECK(nonlinearity > 0.05); // the load is large: a linear body would be off
  CHECK(error < 0.03);
}
