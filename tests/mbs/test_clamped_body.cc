// The ground-clamped floating-frame body, M_red q'' + D q' + K_red q = Psi^T f, against
// exact solutions: the full truss model's static deflection (all modes kept) and the
// modal-superposition response to a step load.
#include "mbs/floating_frame_body.h"
#include "mbs/joint.h"
#include "mbs/multibody_system.h"
#include "mbs/rigid_body.h"
#include "truss_beam.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace chipflex;
using namespace chipflex::mbs;
using chipflex::mbs::test::make_truss_beam;
using chipflex::mbs::test::TrussBeamSpec;

TEST_CASE("Clamped body with all modes reaches the full model's static deflection in large steps",
          "[mbs][ffrf][clamped]")
{
  // reference: K_ff u = f of the full truss (clamp DOFs removed). With all modes kept the
  // reduced model is exact; rho_inf = 0 removes the transient within a few steps whose
  // size (1 s) is far beyond every period (the step is not limited by the highest mode).
  TrussBeamSpec spec;
  spec.n_cells = 8;
  spec.n_modes = -1;
  const auto beam = make_truss_beam(spec);
  IntegratorOptions opt;
  opt.rho_infinity = 0;
  MultibodySystem<2> system(opt);
  FloatingFrameOptions fo;
  fo.damping = DampingKind::modal;
  fo.modal_damping_ratio = 0.05;
  const int id = system.add_body(std::make_unique<FloatingFrameBody<2>>(beam.body, fo));
  auto& body = system.body(id);
  body.clamp_to_ground();
  const auto& tip = body.node_set("tip");
  body.set_node_forces(tip, std::vector<Eigen::Vector2d>(tip.size(), Eigen::Vector2d(0.3, -0.2)));
  for (int s = 0; s < 30; ++s)
    system.step(1.0);

  const int n = body.n_nodes();
  const int layers = 2;
  const int nf = 2 * (n - layers);
  const Eigen::MatrixXd kff = beam.stiffness.bottomRightCorner(nf, nf);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(nf);
  for (int node : tip)
    f.segment<2>(2 * (node - layers)) = Eigen::Vector2d(0.3, -0.2);
  const Eigen::VectorXd u = kff.ldlt().solve(f);
  for (int node : tip)
  {
    const Eigen::Vector2d ref = u.segment<2>(2 * (node - layers));
    CHECK((body.node_displacement(node) - ref).norm() <= 1e-8 * ref.norm());
  }
  CHECK((body.node_displacement(0)).norm() == 0.0); // clamp nodes do not move
}

TEST_CASE("Clamped body under a step tip load follows the modal superposition solution",
          "[mbs][ffrf][clamped]")
{
  // reference: undamped step response q_k = p_k / w_k^2 (1 - cos w_k t), p = Psi^T f.
  // Trapezoidal rule (rho_inf = 1): phase error (w h)^2 / 12 per radian.
  TrussBeamSpec spec;
  spec.n_cells = 10;
  spec.n_modes = 3;
  const auto beam = make_truss_beam(spec);
  IntegratorOptions opt;
  opt.rho_infinity = 1;
  MultibodySystem<2> system(opt);
  system.add_body(std::make_unique<FloatingFrameBody<2>>(beam.body));
  auto& body = system.body(0);
  body.clamp_to_ground();
  const auto& tip = body.node_set("tip");
  const Eigen::Vector2d load(0, -0.5);
  body.set_node_forces(tip, std::vector<Eigen::Vector2d>(tip.size(), load));
  const Eigen::MatrixXd& psi = beam.body.psi;
  const int m = body.n_modes();
  Eigen::VectorXd p = Eigen::VectorXd::Zero(m), w2(m);
  for (int node : tip)
    p += psi.middleRows(2 * node, 2).transpose() * load;
  for (int k = 0; k < m; ++k)
    w2(k) = beam.body.stiffness_matrix(k, k);
  const double period1 = 2 * M_PI / std::sqrt(w2(0));
  const double period_m = 2 * M_PI / std::sqrt(w2(m - 1));
  const double h = period_m / 400;
  const int steps = static_cast<int>(2 * period1 / h);
  const int probe = tip[0];
  double max_err = 0, max_ref = 0;
  for (int s = 1; s <= steps; ++s)
  {
    system.step(h);
    Eigen::VectorXd q(m);
    for (int k = 0; k < m; ++k)
      q(k) = p(k) / w2(k) * (1 - std::cos(std::sqrt(w2(k)) * s * h));
    const Eigen::Vector2d ref = psi.middleRows(2 * probe, 2) * q;
    max_err = std::max(max_err, (body.node_displacement(probe) - ref).norm());
    max_ref = std::max(max_ref, ref.norm());
  }
  INFO("max error " << max_err << " of max displacement " << max_ref);
  CHECK(max_err <= 1e-3 * max_ref);
  CHECK(system.last_newton_iterations() == 1); // linear: one exact iteration per step
}

namespace
{
/// Static tip displacement of a clamp-mode body whose frame is held by a FixedJoint to a
/// rigid carrier that is itself pinned to ground (joint path) or clamped to ground
/// directly (reference path).
template <int dim>
Eigen::Matrix<double, dim, 1> held_tip_displacement(bool through_joint)
{
  using V = Eigen::Matrix<double, dim, 1>;
  TrussBeamSpec spec;
  spec.dim = dim;
  spec.n_cells = 6;
  spec.n_modes = 5;
  const auto beam = make_truss_beam(spec);
  IntegratorOptions opt;
  opt.rho_infinity = 0;
  MultibodySystem<dim> system(opt);
  FloatingFrameOptions fo;
  fo.damping = DampingKind::modal;
  fo.modal_damping_ratio = 0.1;
  const int id = system.add_body(std::make_unique<FloatingFrameBody<dim>>(beam.body, fo));
  auto& body = system.body(id);
  if (through_joint)
  {
    // a heavy rigid carrier fixed to ground, the flexible body fixed to the carrier
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();
    const int carrier = system.add_body(
        make_rigid_body<dim>(rigid_body_data<dim>(1.0, V::Zero(), inertia, {V::Zero()}, {})));
    system.add_joint(
        std::make_unique<FixedJoint<dim>>(Joint<dim>::ground, V::Zero(), carrier, V::Zero()));
    system.add_joint(std::make_unique<FixedJoint<dim>>(carrier, V::Zero(), id, V::Zero()));
  }
  else
    body.clamp_to_ground();
  const auto& tip = body.node_set("tip");
  V load = V::Zero();
  load(1) = -0.2;
  load(0) = 0.1;
  body.set_node_forces(tip, std::vector<V>(tip.size(), load));
  for (int s = 0; s < 40; ++s)
    system.step(0.05);
  CHECK(system.constraint_violation() < 1e-12);
  return body.node_displacement(tip[0]);
}
} // namespace

TEST_CASE("A body held by fixed joints deflects like the ground-clamped body", "[mbs][joint]")
{
  // reference: the ground-clamped body (exact reduced statics); the joint path goes through
  // FixedJoint constraints in 2D and 3D, multipliers and the full floating-frame terms
  const Eigen::Vector2d a2 = held_tip_displacement<2>(true), b2 = held_tip_displacement<2>(false);
  CHECK((a2 - b2).norm() <= 1e-9 * b2.norm());
  const Eigen::Vector3d a3 = held_tip_displacement<3>(true), b3 = held_tip_displacement<3>(false);
  CHECK((a3 - b3).norm() <= 1e-9 * b3.norm());
  CHECK(b3.norm() > 0);
}

TEST_CASE("Rayleigh and modal damping give the damped-oscillator free decay",
          "[mbs][ffrf][clamped]")
{
  // reference: q(t) = v0 / w_d exp(-zeta w t) sin(w_d t), w_d = w sqrt(1 - zeta^2), with
  // zeta = alpha / (2 w) + beta w / 2 (Rayleigh) or the given modal ratio
  TrussBeamSpec spec;
  spec.n_cells = 8;
  spec.n_modes = 1;
  spec.bar_stiffness = 200;
  const auto beam = make_truss_beam(spec);
  const double w = std::sqrt(beam.body.stiffness_matrix(0, 0));
  for (const DampingKind kind : {DampingKind::rayleigh, DampingKind::modal})
  {
    FloatingFrameOptions fo;
    fo.damping = kind;
    fo.rayleigh_mass = 0.1 * w;
    fo.rayleigh_stiffness = 0.02 / w;
    fo.modal_damping_ratio = 0.03;
    const double zeta = kind == DampingKind::rayleigh ? 0.05 + 0.01 : 0.03;
    IntegratorOptions opt;
    opt.rho_infinity = 1;
    MultibodySystem<2> system(opt);
    system.add_body(std::make_unique<FloatingFrameBody<2>>(beam.body, fo));
    auto& body = system.body(0);
    body.clamp_to_ground();
    body.set_modal_state(Eigen::VectorXd::Zero(1), Eigen::VectorXd::Constant(1, 1e-3));
    const double wd = w * std::sqrt(1 - zeta * zeta);
    const double h = 2 * M_PI / w / 2000;
    double max_err = 0;
    for (int s = 1; s <= 6000; ++s)
    {
      system.step(h);
      const double t = s * h;
      const double ref = 1e-3 / wd * std::exp(-zeta * w * t) * std::sin(wd * t);
      max_err = std::max(max_err, std::abs(body.modal_coordinates()(0) - ref));
    }
    CHECK(max_err < 1e-5 * 1e-3 / w);
  }
}
