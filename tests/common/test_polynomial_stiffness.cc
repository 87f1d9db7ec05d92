// The reduced St Venant-Kirchhoff force is the gradient of its energy and the tangent its
// Jacobian (checked by central differences: a wrong symmetry factor or a misplaced
// permutation in the unpacking fails by O(1)); the nonlinear datasets round-trip through the
// body file, and a version-1 file still loads as a linear body.

#include "common/hdf5_file.h"
#include "common/polynomial_stiffness.h"
#include "common/reduced_body_file.h"

#include <catch2/catch.hpp>
#include <cstdio>

using namespace chipflex;

namespace
{
/// A random fully symmetric polynomial (any sorted entries define one).
PolynomialStiffness random_polynomial(int m, int n_used, std::vector<double>* q3 = nullptr,
                                      std::vector<double>* q4 = nullptr)
{
  std::srand(7);
  Eigen::MatrixXd k = Eigen::MatrixXd::Random(m, m);
  k = (k * k.transpose()).eval();
  std::vector<double> quadratic(n_sorted_triples(m)), cubic(n_sorted_quadruples(m));
  for (auto& v : quadratic)
    v = Eigen::internal::random<double>(-1, 1);
  for (auto& v : cubic)
    v = Eigen::internal::random<double>(-1, 1);
  if (q3)
    *q3 = quadratic;
  if (q4)
    *q4 = cubic;
  return PolynomialStiffness(k, quadratic, cubic, n_used);
}
} // namespace

TEST_CASE("reduced SVK polynomial: force = dV/dq, tangent = df/dq", "[common][nonlinear]")
{
  for (const int n_used : {5, 3})
  {
    const auto p = random_polynomial(5, n_used);
    const int m = p.size();
    REQUIRE(m == n_used);
    const Eigen::VectorXd q = Eigen::VectorXd::Random(m);
    Eigen::VectorXd f(m), fp(m), fm(m);
    Eigen::MatrixXd kt;
    p.evaluate(q, f, &kt);
    const double h = 1e-5;
    for (int i = 0; i < m; ++i)
    {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(m);
      e(i) = h;
      const double dv = (p.energy(q + e) - p.energy(q - e)) / (2 * h);
      CHECK(std::abs(dv - f(i)) < 1e-7 * f.norm());
      p.evaluate(q + e, fp);
      p.evaluate(q - e, fm);
      CHECK(((fp - fm) / (2 * h) - kt.col(i)).norm() < 1e-7 * kt.norm());
    }
    CHECK((kt - kt.transpose()).norm() < 1e-12 * kt.norm());
    Eigen::VectorXd f0(m);
    p.evaluate(Eigen::VectorXd::Zero(m), f0);
    CHECK(f0.norm() == 0);
  }
}

TEST_CASE("nonlinear body file: v2 round trip, v1 loads as a linear body", "[common][nonlinear]")
{
  ReducedBodyData b;
  b.dim = 2;
  b.youngs_modulus = 1e7;
  b.poisson_ratio = 0.3;
  b.density = 1000;
  b.model = "plane_strain";
  b.mesh_file = "beam.msh";
  b.mesh_hash = "0123456789abcdef";
  b.element_degree = 2;
  b.tool_version = "chipflex test";
  const int n = 4, m = 3;
  b.nodes = Eigen::MatrixXd::Random(n, 2);
  b.skin_nodes = {0, 1, 2, 3};
  b.skin_faces = Eigen::MatrixXi(1, 2);
  b.skin_faces << 0, 1;
  b.psi = Eigen::MatrixXd::Random(2 * n, m);
  b.frequencies_hz = Eigen::VectorXd::Ones(m);
  b.mode_kinds = {"normal", "normal", "derivative:1,1"};
  b.mass_matrix = Eigen::MatrixXd::Identity(m, m);
  b.stiffness_matrix = Eigen::MatrixXd::Identity(m, m);
  b.mass = 1;
  b.center_of_mass = Eigen::VectorXd::Zero(2);
  b.inertia_tensor = Eigen::Matrix3d::Identity();
  b.c_xx = Eigen::MatrixXd::Identity(2, 2);
  b.translation_coupling = Eigen::MatrixXd::Zero(2, m);
  b.c_x_psi.assign(m, Eigen::MatrixXd::Zero(2, 2));
  b.c_psi_psi.assign(m * m, Eigen::MatrixXd::Zero(2, 2));
  random_polynomial(m, m, &b.quadratic_stiffness, &b.cubic_stiffness);
  b.n_modal_derivatives = 1;
  write_reduced_body("nonlinear_body.h5", b);
  const auto r = read_reduced_body("nonlinear_body.h5");
  CHECK(r.file_version == 2);
  CHECK(r.nonlinear());
  CHECK(r.n_modal_derivatives == 1);
  CHECK(r.quadratic_stiffness == b.quadratic_stiffness);
  CHECK(r.cubic_stiffness == b.cubic_stiffness);

  b.quadratic_stiffness.clear();
  b.cubic_stiffness.clear();
  write_reduced_body("linear_body.h5", b);
  {
    Hdf5File f("linear_body.h5", Hdf5File::Mode::update);
    f.write_attribute("/meta", "format_version", std::int64_t(1));
  }
  const auto v1 = read_reduced_body("linear_body.h5");
  CHECK(v1.file_version == 1);
  CHECK_FALSE(v1.nonlinear());
  CHECK(v1.psi == b.psi);
  std::remove("nonlinear_body.h5");
  std::remove("linear_body.h5");
}
