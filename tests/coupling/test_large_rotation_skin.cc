// The large-rotation skin of a clamped reduced beam (coupling/large_rotation_beam_skin.h)
// against the Euler elastica. Reference: a cantilever under a dead tip load P normal to
// its undeformed axis obeys EI theta'' = -P cos(theta), theta(0) = 0, theta'(L) = 0
// (Bisshopp & Drucker 1945; tabulated by Mattiasson 1981: for alpha = P L^2 / EI = 1,
// 2, 3 the tip moves 0.3017, 0.4935, 0.6033 L across and 0.0564, 0.1606, 0.2544 L back
// along the axis). The reference is integrated here by shooting, and checked against
// those tabulated values.
//
// The FE side is the real pipeline: `chipflex mesh gate`'s structured mesh, reduced with
// 8 clamped normal modes + the static mode of the upstream pressure (the elastic-gate
// benchmark's basis). The static equilibrium K_red q = J(q)^T f of the reduced body seen
// through the large-rotation skin must put the tip where the elastica does (2 % of the
// elastica's displacement), and the linear skin must visibly not (it cannot shorten).

#include "coupling/large_rotation_beam_skin.h"
#include "fem_test_support.h"

#include <Eigen/Dense>
#include <algorithm>
#include <catch2/catch.hpp>
#include <functional>

using namespace chipflex;
using Vector = Eigen::Vector2d;

namespace
{
struct ElasticaTip
{
  double across, back; ///< tip displacement normal to / back along the axis, / L
};

/// theta'' = -alpha cos(theta) on s in [0, 1], theta(0) = 0, theta'(1) = 0: shoot on
/// theta'(0) (RK4, 2000 steps), bisection; returns the tip displacement / L.
ElasticaTip elastica(double alpha)
{
  const int n = 2000;
  const double h = 1.0 / n;
  auto shoot = [&](double kappa0, ElasticaTip* tip)
  {
    // state: theta, theta', x, y
    Eigen::Vector4d y(0, kappa0, 0, 0);
    auto rhs = [&](const Eigen::Vector4d& z)
    { return Eigen::Vector4d(z(1), -alpha * std::cos(z(0)), std::cos(z(0)), std::sin(z(0))); };
    for (int i = 0; i < n; ++i)
    {
      const Eigen::Vector4d k1 = rhs(y), k2 = rhs(y + 0.5 * h * k1), k3 = rhs(y + 0.5 * h * k2),
                            k4 = rhs(y + h * k3);
      y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    if (tip)
      *tip = {y(3), 1 - y(2)};
    return y(1);
  };
  double lo = 0, hi = alpha; // theta'(1) > 0 at kappa0 = alpha (the linear curvature)
  for (int it = 0; it < 100; ++it)
  {
    const double mid = 0.5 * (lo + hi);
    (shoot(mid, nullptr) > 0 ? hi : lo) = mid;
  }
  ElasticaTip tip{};
  shoot(0.5 * (lo + hi), &tip);
  return tip;
}

ReducedBodyData reduced_gate()
{
  fem::ReductionSettings s;
  s.mesh_file = fem::testing::gate_mesh(0.005 / 4);
  s.clamp_group = "clamp";
  s.n_modes = 8;
  s.static_modes = {"pressure:xmin"};
  return fem::reduce_body(s);
}

/// Static equilibrium of the clamped body under the dead tip load `load` (world, N per
/// metre), seen through `skin`: Newton on r(q) = J(q)^T f - K_red q with a
/// finite-difference Jacobian (n_modes is small). Returns the tip's mean displacement.
template <class Skin>
Vector tip_displacement(mbs::FloatingFrameBody<2>& body, Skin& skin, const Vector& load,
                        const std::function<Vector()>& tip_position)
{
  const auto& skin_ids = body.skin_node_ids();
  const auto& tip = body.node_set("tip");
  std::vector<std::size_t> on_tip; // skin indices of the tip nodes
  for (std::size_t i = 0; i < skin_ids.size(); ++i)
    if (std::find(tip.begin(), tip.end(), skin_ids[i]) != tip.end())
      on_tip.push_back(i);
  std::vector<Vector> full(skin_ids.size(), Vector::Zero());
  for (std::size_t i : on_tip)
    full[i] = load / double(on_tip.size());
  std::vector<Vector> f = full;

  const int m = body.n_modes();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(m);
  auto residual = [&](const Eigen::VectorXd& q)
  {
    body.set_modal_state(q, zero);
    skin.set_skin_forces(f);
    Eigen::VectorXd r(m);
    body.forces(Vector::Zero(), r);
    return r;
  };
  const Vector start = tip_position();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m);
  // Load in increments: the elastica's equilibrium path is followed, not jumped.
  for (int stage = 1; stage <= 10; ++stage)
  {
    for (std::size_t i = 0; i < f.size(); ++i)
      f[i] = full[i] * (stage / 10.0);
    for (int it = 0; it < 30; ++it)
    {
      const Eigen::VectorXd r = residual(q);
      Eigen::MatrixXd jac(m, m);
      const double eps = 1e-7 * std::max(1.0, q.norm());
      for (int k = 0; k < m; ++k)
      {
        Eigen::VectorXd qk = q;
        qk(k) += eps;
        jac.col(k) = (residual(qk) - r) / eps;
      }
      const Eigen::VectorXd dq = jac.fullPivLu().solve(-r);
      q += dq;
      if (dq.norm() <= 1e-12 * std::max(1e-12, q.norm()))
        break;
    }
  }
  body.set_modal_state(q, zero);
  return tip_position() - start;
}
} // namespace

TEST_CASE("the shooting elastica reproduces the tabulated tip displacements", "[coupling]")
{
  const double across[] = {0.30172, 0.49346, 0.60325}, back[] = {0.05643, 0.16064, 0.25442};
  for (int k = 0; k < 3; ++k)
  {
    const ElasticaTip tip = elastica(k + 1.0);
    CHECK(tip.across == Approx(across[k]).epsilon(2e-4));
    CHECK(tip.back == Approx(back[k]).epsilon(2e-4));
  }
}

TEST_CASE("the large-rotation skin of the reduced gate follows the elastica", "[coupling]")
{
  const ReducedBodyData data = reduced_gate();
  const fem::Material material;
  const double t = 0.005, length = 0.079;
  const double ei = material.youngs_modulus / (1 - std::pow(material.poisson_ratio, 2)) *
                    std::pow(t, 3) / 12; // plane strain, per metre
  // The gate hangs from its clamp (top, y = L) down to its tip (y = 0): axis -y, the
  // load pushes it downstream (+x).
  for (double alpha : {1.0, 3.0})
  {
    const double p = alpha * ei / (length * length);
    const ElasticaTip ref = elastica(alpha);
    const Vector expected(ref.across * length, ref.back * length); // +x across, up (back)

    mbs::FloatingFrameBody<2> body(data);
    body.clamp_to_ground();
    coupling::LargeRotationBeamSkin skin(body, "clamp", "tip");
    const Vector u =
        tip_displacement(body, skin, Vector(p, 0), [&] { return skin.tip_position(); });
    INFO("alpha = " << alpha << ": tip moved " << u.transpose() << " m, elastica "
                    << expected.transpose() << " m");
    CHECK((u - expected).norm() <= 0.02 * expected.norm());

    // The linear skin (x = xbar + Psi q) keeps the tip at its height.
    mbs::FloatingFrameBody<2> linear(data);
    linear.clamp_to_ground();
    const auto& tip = linear.node_set("tip");
    auto linear_tip = [&]
    {
      Vector sum = Vector::Zero();
      for (int i : tip)
        sum += linear.node_position(i);
      return Vector(sum / double(tip.size()));
    };
    const Vector ul = tip_displacement(linear, linear, Vector(p, 0), linear_tip);
    INFO("linear skin: tip moved " << ul.transpose() << " m");
    CHECK(std::abs(ul.y()) < 0.1 * expected.y());
    CHECK((ul - expected).norm() > 0.1 * expected.norm());
  }
}
