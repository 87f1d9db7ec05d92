// Static correction modes against the full FE solution (compare_with_full): with the
// load's own static mode the reduced static tip deflection equals the full one (it spans
// K^-1 f exactly); with normal modes only it converges slowly, as modal truncation of a
// static load must (the residual flexibility sum_k>m phi_k phi_k^T / omega_k^2 is lost).
#include "common/reduced_body_file.h"
#include "compare/compare_with_full.h"
#include "fem_test_support.h"

#include <catch2/catch.hpp>

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
