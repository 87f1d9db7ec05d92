// Static correction modes against the full FE solution (compare_with_full): with the
// load's own static mode the reduced static tip deflection equals the full one (it spans
// K^-1 f exactly); with normal modes only it converges slowly, as modal truncation of a
// static load must (the residual flexibility sum_k>m phi_k phi_k^T / omega_k^2 is lost).
#include "common/reduced_body_file.h"
#include "compare/compare_with_full.h"
#include "fem_test_support.h"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>
#include <cmath>

using namespace chipflex;
using namespace chipflex::compare;
using namespace chipflex::fem;
using namespace chipflex::fem::testing;

namespace
{
CompareResult reduce_and_compare(const std::string& mesh, unsigned int modes,
                                 std::vector<std::string> static_modes, const std::string& load)
{
  ReductionSettings s;
  s.material = {1.2e7, 0.4, 1100, false}; // the gate's rubber
  s.mesh_file = mesh;
  s.clamp_group = "clamp";
  s.n_modes = modes;
  s.static_modes = std::move(static_modes);
  const std::string body = scratch("static_" + std::to_string(modes) + "_" +
                                   std::to_string(s.static_modes.size()) + ".h5");
  write_reduced_body(body, reduce_body(s));
  CompareSettings c;
  c.mesh_file = mesh;
  c.body_file = body;
  c.load = load;
  return compare_with_full(c);
}
} // namespace

TEST_CASE("static tip deflection: one static mode matches the full FE model", "[fem]")
{
  const std::string mesh = gate_mesh(0.005 / 4);
  const std::string load = "force:tip:1,0";
  const auto with_static = reduce_and_compare(mesh, 4, {load}, load);
  INFO("static error with 4 normal + 1 static mode: " << with_static.static_rel_error);
  CHECK(with_static.static_rel_error < 1e-6);
  // Euler-Bernoulli tip deflection F L^3 / (3 E' I) (per metre; shear adds ~1 %).
  const double e = 1.2e7 / (1 - 0.16), i = std::pow(0.005, 3) / 12;
  CHECK(with_static.static_full[0] == Approx(std::pow(0.079, 3) / (3 * e * i)).epsilon(0.02));
  // The step response: the static mode carries the quasi-static part exactly.
  CHECK(with_static.transient_rel_error < 0.01);

  std::vector<double> errors;
  for (unsigned int m : {1u, 2u, 4u, 8u})
  {
    const auto normal_only = reduce_and_compare(mesh, m, {}, load);
    errors.push_back(normal_only.static_rel_error);
  }
  INFO("normal modes only, 1/2/4/8 modes: " << errors[0] << " " << errors[1] << " " << errors[2]
                                            << " " << errors[3]);
  for (std::size_t k = 1; k < errors.size(); ++k)
    CHECK(errors[k] < errors[k - 1]);
  // Slow: even 8 normal modes stay orders of magnitude worse than one static mode.
  CHECK(errors.back() > 1e-5);
  CHECK(errors.back() > 100 * with_static.static_rel_error);
}

TEST_CASE("two static modes: K_red diagonal, frequencies are the reduced pair's", "[fem]")
{
  // Two load patterns on the gate: a tip force and pressure on the upstream face. Their
  // static modes, Gram-Schmidt against 4 normal modes, give a full 2 x 2 block of K_red
  // (measured before the rotation: off-diagonal 7.0e6 against a diagonal 1.3e7 and 2.5e7,
  // and "frequencies" 574 and 799 Hz from that diagonal, where the reduced pair's Ritz
  // frequencies are 499 and 847 Hz). After the rotation to Ritz vectors K_red must be
  // diagonal to round-off, M_red the identity, the reported frequencies the eigenvalues of
  // (K_red, M_red), and the span unchanged: each load's static response still exact.
  const std::string mesh = gate_mesh(0.005 / 4);
  const std::vector<std::string> loads = {"force:tip:1,0", "pressure:xmin"};
  ReductionSettings s;
  s.material = {1.2e7, 0.4, 1100, false}; // the gate's rubber
  s.mesh_file = mesh;
  s.clamp_group = "clamp";
  s.n_modes = 4;
  s.static_modes = loads;
  const ReducedBodyData body = reduce_body(s);
  const int m = body.n_modes();
  REQUIRE(m == 6);
  CHECK(body.mode_kinds[4] == "static:force:tip:1,0");
  CHECK(body.mode_kinds[5] == "static:pressure:xmin");

  const Eigen::MatrixXd& k = body.stiffness_matrix;
  const Eigen::MatrixXd off_diagonal = k - Eigen::MatrixXd(k.diagonal().asDiagonal());
  INFO("K_red:\n" << k);
  CHECK(off_diagonal.cwiseAbs().maxCoeff() < 1e-12 * k.diagonal().maxCoeff());
  CHECK((body.mass_matrix - Eigen::MatrixXd::Identity(m, m)).norm() < 1e-10);

  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> pair(k, body.mass_matrix);
  REQUIRE(pair.info() == Eigen::Success);
  for (int i = 0; i < m; ++i)
  {
    const double ritz_hz = std::sqrt(pair.eigenvalues()[i]) / (2 * M_PI);
    INFO("mode " << i + 1 << ": reported " << body.frequencies_hz[i] << " Hz, Ritz " << ritz_hz
                 << " Hz");
    CHECK(body.frequencies_hz[i] == Approx(ritz_hz).epsilon(1e-12));
    if (i > 0)
      CHECK(body.frequencies_hz[i] >= body.frequencies_hz[i - 1]);
  }
  // Courant-Fischer: vectors M-orthogonal to the first four modes have Rayleigh quotients at
  // or above the fifth eigenvalue, so the static Ritz frequencies lie above the normal ones.
  CHECK(body.frequencies_hz[4] > body.frequencies_hz[3]);

  // The rotation keeps the span: K^-1 f of either load is still in it, so the reduced
  // static response equals the full one for both loads.
  const std::string file = scratch("two_static.h5");
  write_reduced_body(file, body);
  for (const auto& load : loads)
  {
    CompareSettings c;
    c.mesh_file = mesh;
    c.body_file = file;
    c.load = load;
    c.duration = 1e-3; // one time step: the static part is what is checked here
    const CompareResult r = compare_with_full(c);
    INFO(load << ": static relative error " << r.static_rel_error);
    CHECK(r.static_rel_error < 1e-6);
  }
}
