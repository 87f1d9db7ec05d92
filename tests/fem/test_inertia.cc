// Mass, centre of mass and inertia tensor of a box from the consistent mass matrix: exact
// (to round-off) because the FE space holds the linear coordinate fields exactly and the
// Gauss rule integrates their products exactly. Reference: m = rho V, c = box centre,
// I_xx = m (b^2 + c^2) / 12 etc.
#include "common/reduced_body_file.h"
#include "fem_test_support.h"

#include <catch2/catch.hpp>

using namespace chipflex;
using namespace chipflex::fem;
using namespace chipflex::fem::testing;

namespace
{
void check_invariants(const ReducedBodyData& body)
{
  const int m = body.n_modes();
  // Mass-orthonormal basis, and M_red is the trace of C(psi_k, psi_l).
  CHECK((body.mass_matrix - Eigen::MatrixXd::Identity(m, m)).norm() < 1e-10);
  for (int k = 0; k < m; ++k)
    for (int l = 0; l < m; ++l)
      CHECK(body.c_psi_psi[k * m + l].isApprox(body.c_psi_psi[l * m + k].transpose(), 1e-12));
  CHECK((body.stiffness_matrix - body.stiffness_matrix.transpose()).norm() <=
        1e-12 * body.stiffness_matrix.norm());
}
} // namespace

TEST_CASE("3D box: mass, centre of mass and inertia tensor exact", "[fem]")
{
  const double a = 0.03, b = 0.02, c = 0.01, rho = 2700;
  for (const bool simplex : {false, true})
    for (const unsigned int degree : {1u, 2u})
    {
      ReductionSettings s;
      s.material = {7e10, 0.33, rho, false};
      s.mesh_file = strip_mesh(a, b, c, 0.005, simplex);
      s.degree = degree;
      s.n_modes = 2;
      s.clamp_group = "clamp";
      const auto body = reduce_body(s);
      const double mass = rho * a * b * c;
      INFO((simplex ? "tetrahedra" : "hexahedra") << ", degree " << degree);
      CHECK(body.mass == Approx(mass).epsilon(1e-12));
      CHECK(body.center_of_mass[0] == Approx(a / 2).epsilon(1e-12));
      CHECK(body.center_of_mass[1] == Approx(b / 2).epsilon(1e-12));
      CHECK(body.center_of_mass[2] == Approx(c / 2).epsilon(1e-12));
      Eigen::Matrix3d expected = Eigen::Matrix3d::Zero();
      expected(0, 0) = mass * (b * b + c * c) / 12;
      expected(1, 1) = mass * (a * a + c * c) / 12;
      expected(2, 2) = mass * (a * a + b * b) / 12;
      CHECK((body.inertia_tensor - expected).norm() < 1e-12 * expected.norm());
      // C(x, x) about the origin = J about the centre + m c c^T (parallel axes).
      Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
      second.diagonal() << mass * a * a / 3, mass * b * b / 3, mass * c * c / 3;
      second(0, 1) = second(1, 0) = mass * a * b / 4;
      second(0, 2) = second(2, 0) = mass * a * c / 4;
      second(1, 2) = second(2, 1) = mass * b * c / 4;
      CHECK((body.c_xx - second).norm() < 1e-12 * second.norm());
      check_invariants(body);
    }
}

TEST_CASE("2D rectangle: mass and inertia per metre of depth exact", "[fem]")
{
  const double t = 0.005, l = 0.079, rho = 1100;
  ReductionSettings s;
  s.material = {1.2e7, 0.4, rho, false}; // the gate's rubber
  s.mesh_file = gate_mesh(t / 2);
  s.n_modes = 3;
  s.static_modes = {"force:tip:1,0"};
  const auto body = reduce_body(s);
  const double mass = rho * t * l;
  CHECK(body.mass == Approx(mass).epsilon(1e-12));
  CHECK(body.center_of_mass[0] == Approx(t / 2).epsilon(1e-12));
  CHECK(body.center_of_mass[1] == Approx(l / 2).epsilon(1e-12));
  // z out of plane: I_xx = int y^2, I_yy = int x^2, I_zz = their sum.
  CHECK(body.inertia_tensor(0, 0) == Approx(mass * l * l / 12).epsilon(1e-12));
  CHECK(body.inertia_tensor(1, 1) == Approx(mass * t * t / 12).epsilon(1e-12));
  CHECK(body.inertia_tensor(2, 2) == Approx(mass * (t * t + l * l) / 12).epsilon(1e-12));
  CHECK(std::abs(body.inertia_tensor(0, 1)) < 1e-14 * body.inertia_tensor(0, 0));
  check_invariants(body);
  // The free-free static mode (inertia relief) carries no rigid motion either.
  CHECK(body.mode_kinds.back() == "static:force:tip:1,0");
  CHECK(body.translation_coupling.norm() < 1e-9 * std::sqrt(body.mass));
}
