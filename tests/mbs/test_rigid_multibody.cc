// Rigid bodies with joints and torsion springs: pendulum periods (exact elliptic-integral
// value), the seed paper's spring chains under a static tip force, checkpoints.
#include "common/input_error.h"
#include "elastic_gate_chain.h"
#include "mbs/composite_skin.h"
#include "mbs/multibody_system.h"
#include "mbs/rigid_body.h"
#include "mbs/rigid_chain.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace chipflex;
using namespace chipflex::mbs;

namespace
{
constexpr double g0 = 9.81;

/// Exact period of a physical pendulum released from rest at amplitude theta0:
/// T = 4 sqrt(I / (m g d)) K(sin(theta0 / 2)), K the complete elliptic integral.
double exact_period(double inertia_hinge, double mass, double d, double theta0)
{
  return 4 * std::sqrt(inertia_hinge / (mass * g0 * d)) * std::comp_ellint_1(std::sin(theta0 / 2));
}

/// Period from the times of successive downward zero crossings of angle(t).
template <class Angle>
double measure_period(MultibodySystem<2>& system, double h, double t_end, Angle angle)
{
  std::vector<double> crossings;
  double previous = angle();
  while (system.time() < t_end)
  {
    system.step(h);
    const double now = angle();
    if (previous > 0 && now <= 0)
      crossings.push_back(system.time() - h * now / (now - previous));
    previous = now;
  }
  REQUIRE(crossings.size() >= 3);
  return (crossings.back() - crossings.front()) / (crossings.size() - 1);
}

double planar_pendulum_period(double theta0, IntegratorOptions::Scheme scheme, double steps_per_t,
                              double& reference)
{
  const double l = 0.5, t = 0.02, rho = 1000;
  IntegratorOptions opt;
  opt.scheme = scheme;
  opt.rho_infinity = 1;
  MultibodySystem<2> system(opt);
  system.set_gravity({0, -g0});
  const ReducedBodyData link = rectangular_link_data(l, t, rho);
  const int b = system.add_body(make_rigid_body<2>(link));
  system.body(b).set_pose(Eigen::Vector2d::Zero(), theta0);
  system.add_joint(std::make_unique<RevoluteJoint<2>>(Joint<2>::ground, Eigen::Vector2d::Zero(), b,
                                                      Eigen::Vector2d::Zero()));
  const double m = link.mass;
  reference = exact_period(m * l * l / 3 + m * t * t / 12, m, l / 2, theta0);
  const double period = measure_period(system, reference / steps_per_t, 3.2 * reference,
                                       [&] { return system.body(b).angle(); });
  CHECK(system.constraint_violation() < 1e-12);
  return period;
}
} // namespace

TEST_CASE("Planar pendulum period matches the exact elliptic-integral value", "[mbs][rigid]")
{
  // small amplitude (0.05 rad) and large (1.2 rad, 9.5 % longer than the linear period)
  for (double theta0 : {0.05, 1.2})
  {
    double ref = 0;
    const double period =
        planar_pendulum_period(theta0, IntegratorOptions::Scheme::generalized_alpha, 2000, ref);
    INFO("theta0 " << theta0 << " period " << period << " exact " << ref << " rel. error "
                   << period / ref - 1);
    CHECK(std::abs(period / ref - 1) < 2e-6);
  }
}

TEST_CASE("Planar pendulum with the explicit scheme and constraint projection", "[mbs][rigid]")
{
  double ref = 0;
  const double period =
      planar_pendulum_period(0.5, IntegratorOptions::Scheme::symplectic_euler, 5000, ref);
  INFO("explicit: period " << period << " exact " << ref << " rel. error " << period / ref - 1);
  CHECK(std::abs(period / ref - 1) < 1e-4);
}

TEST_CASE("Spatial pendulum (quaternion body, 3D revolute joint) has the exact period",
          "[mbs][rigid]")
{
  // A box hanging along -z from a hinge about the x axis: the same planar motion in 3D.
  const double a = 0.04, b = 0.02, l = 0.6, m = 2.0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  inertia(0, 0) = m * (b * b + l * l) / 12;
  inertia(1, 1) = m * (a * a + l * l) / 12;
  inertia(2, 2) = m * (a * a + b * b) / 12;
  const ReducedBodyData box = rigid_body_data<3>(m, Eigen::Vector3d(0, 0, -l / 2), inertia,
                                                 {Eigen::Vector3d(0, 0, -l)}, {});
  IntegratorOptions opt;
  opt.rho_infinity = 1;
  MultibodySystem<3> system(opt);
  system.set_gravity({0, 0, -g0});
  const int id = system.add_body(make_rigid_body<3>(box));
  const double theta0 = 0.8;
  system.body(id).set_pose(Eigen::Vector3d::Zero(),
                           Eigen::AngleAxisd(theta0, Eigen::Vector3d::UnitX()).toRotationMatrix());
  system.add_joint(std::make_unique<RevoluteJoint<3>>(
      Joint<3>::ground, Eigen::Vector3d::Zero(), id, Eigen::Vector3d::Zero(),
      Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitX()));
  const double ref = exact_period(inertia(0, 0) + m * l * l / 4, m, l / 2, theta0);
  const double h = ref / 2000;
  std::vector<double> crossings;
  auto angle = [&]
  {
    const Eigen::Matrix3d r = system.body(id).rotation();
    return std::atan2(r(2, 1), r(1, 1)); // rotation about x
  };
  double previous = angle();
  while (system.time() < 3.2 * ref)
  {
    system.step(h);
    const double now = angle();
    if (previous > 0 && now <= 0)
      crossings.push_back(system.time() - h * now / (now - previous));
    previous = now;
  }
  REQUIRE(crossings.size() == 3);
  const double period = (crossings[2] - crossings[0]) / 2;
  INFO("spatial: period " << period << " exact " << ref << " rel. error " << period / ref - 1);
  CHECK(std::abs(period / ref - 1) < 2e-6);
  CHECK(system.constraint_violation() < 1e-12);
  CHECK(std::abs(system.body(id).point_position({0, 0, -l}).x()) < 1e-12); // stays in the plane
}

namespace
{
/// Exact equilibrium of n links (length l, springs c) under a horizontal tip force f:
/// c phi_i = f l sum_{j >= i} cos(theta_j), theta_j = sum_{k <= j} phi_k. Returns the tip x.
double exact_chain_tip(int n, double l, double c, double f)
{
  std::vector<double> phi(n, 0.0);
  for (int it = 0; it < 500; ++it)
  {
    std::vector<double> theta(n);
    double sum = 0;
    for (int j = 0; j < n; ++j)
      theta[j] = sum += phi[j];
    for (int i = 0; i < n; ++i)
    {
      double cs = 0;
      for (int j = i; j < n; ++j)
        cs += std::cos(theta[j]);
      phi[i] = f * l / c * cs;
    }
  }
  double x = 0, sum = 0;
  for (int j = 0; j < n; ++j)
    x += l * std::sin(sum += phi[j]);
  return x;
}

double chain_static_tip(int n_links, double force)
{
  IntegratorOptions opt;
  opt.rho_infinity = 0.5;
  MultibodySystem<2> system(opt);
  RigidChainSpec gate = testing::elastic_gate_chain(n_links);
  gate.spring_damping = 0.05;
  const RigidChain chain = add_rigid_chain(system, gate);
  // the force at the middle of the free edge, split on the two tip corners
  auto& last = system.body(chain.links.back());
  last.set_node_forces(last.node_set("tip"),
                       {Eigen::Vector2d(force / 2, 0), Eigen::Vector2d(force / 2, 0)});
  for (int s = 0; s < 3000; ++s)
    system.step(1e-3);
  return chain.tip_position(system).x();
}
} // namespace

TEST_CASE("Rigid-chain gates under a static tip force: F L^2 / c and the n-link analogues",
          "[mbs][chain]")
{
  // Small force: tip displacement sum_{k=1..n} k^2 F L^2 / c (each joint i carries the
  // moment F (n - i + 1) L), i.e. 1, 5 and 14 F L^2 / c for 1, 2 and 3 links.
  // Large force: the exact nonlinear equilibrium above.
  const double k2[] = {1, 5, 14};
  for (int n = 1; n <= 3; ++n)
  {
    const RigidChainSpec gate = testing::elastic_gate_chain(n);
    const double l = gate.total_length / n, c = gate.spring_rate;
    const double f_small = 1e-4 * c / (n * l);
    const double linear = k2[n - 1] * f_small * l * l / c;
    const double small = chain_static_tip(n, f_small);
    INFO(n << " links: small-force tip " << small << " vs " << linear << " rel. error "
           << small / linear - 1);
    CHECK(std::abs(small / linear - 1) < 1e-6);
    const double f_large = 0.4 * c / (n * l);
    const double exact = exact_chain_tip(n, l, c, f_large);
    const double large = chain_static_tip(n, f_large);
    INFO(n << " links: large-force tip " << large << " vs exact " << exact << " rel. error "
           << large / exact - 1);
    CHECK(std::abs(large / exact - 1) < 1e-8);
  }
}

TEST_CASE("Multibody checkpoint restores the run bit for bit", "[mbs][chain]")
{
  MultibodySystem<2> system;
  system.set_gravity({0, -g0});
  const RigidChain chain = add_rigid_chain(system, testing::elastic_gate_chain(3));
  system.body(chain.links[0]).set_frame_velocity({0, 0}, Eigen::Matrix<double, 1, 1>(5.0));
  for (int s = 0; s < 50; ++s)
    system.step(2e-4);
  const std::vector<double> saved = system.save_state();
  for (int s = 0; s < 50; ++s)
    system.step(2e-4);
  const Eigen::Vector2d tip = chain.tip_position(system);
  const double t = system.time();
  system.restore_state(saved);
  for (int s = 0; s < 50; ++s)
    system.step(2e-4);
  CHECK(chain.tip_position(system) == tip);
  CHECK(system.time() == t);
  CHECK(tip.x() != 0); // the chain did swing
  CHECK_THROWS_AS(system.restore_state(std::vector<double>(saved.begin(), saved.end() - 1)),
                  InputError);
}

TEST_CASE("A chain's composite skin moves with its links and splits its forces", "[mbs][chain]")
{
  MultibodySystem<2> system;
  const RigidChain chain = add_rigid_chain(system, testing::elastic_gate_chain(2));
  std::vector<FloatingFrameBody<2>*> links;
  for (int l : chain.links)
    links.push_back(&system.body(l));
  CompositeSkin<2> skin(links);
  // link 0: rounded at both hinges, 4 corners + 2 x 7 arc nodes; link 1: top only
  const int n0 = int(links[0]->n_skin_nodes()), n = n0 + int(links[1]->n_skin_nodes());
  REQUIRE(n0 == 18);
  REQUIRE(skin.n_skin_nodes() == std::size_t(n));
  REQUIRE(skin.skin_faces().size() == std::size_t(n));
  CHECK(skin.skin_faces()[n0][0] == n0); // second link's faces shifted by n0 nodes
  std::vector<Eigen::Vector2d> x;
  skin.skin_positions(x);
  CHECK(x[n0].y() == Approx(-0.079)); // the second link's bottom-left corner
  // a uniform push on the skin turns the chain (fluid forces in, motion out)
  skin.set_skin_forces(std::vector<Eigen::Vector2d>(n, Eigen::Vector2d(0.5 * 8 / n, 0)));
  for (int s = 0; s < 20; ++s)
    system.step(1e-3);
  std::vector<Eigen::Vector2d> v;
  skin.skin_velocities(v);
  CHECK(v[0].x() > 0);
  CHECK(v[n0].x() > v[0].x());
}

TEST_CASE("A system whose only body is clamped steps and stays put", "[mbs][rigid]")
{
  // A rigid body clamped to ground leaves the system no velocities: every scheme must
  // still advance its time (the generalised-alpha step once crashed on the empty vectors).
  for (const auto scheme :
       {IntegratorOptions::Scheme::generalized_alpha, IntegratorOptions::Scheme::symplectic_euler,
        IntegratorOptions::Scheme::momentum_midpoint})
  {
    IntegratorOptions opt;
    opt.scheme = scheme;
    MultibodySystem<2> system(opt);
    system.set_gravity({0, -g0});
    const int b = system.add_body(make_rigid_body<2>(rectangular_link_data(0.5, 0.02, 1000)));
    system.body(b).set_pose(Eigen::Vector2d(0.1, 0.2), 0.3);
    system.body(b).clamp_to_ground();
    for (int k = 0; k < 10; ++k)
      system.step(1e-3);
    CHECK(std::abs(system.time() - 1e-2) < 1e-15);
    CHECK(system.body(b).position().isApprox(Eigen::Vector2d(0.1, 0.2)));
    CHECK(system.body(b).angle() == 0.3);
  }
}
