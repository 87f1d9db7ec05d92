// A free-floating flexible body: conservation of linear and angular momentum and energy
// (no damping, no loads), and the rigid-elastic coupling of a beam spun up about a hinge.
#include "mbs/floating_frame_body.h"
#include "mbs/multibody_system.h"
#include "truss_beam.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace chipflex;
using namespace chipflex::mbs;
using chipflex::mbs::test::make_truss_beam;
using chipflex::mbs::test::TrussBeamSpec;

TEST_CASE("Free flexible body: momentum and energy conserved over 1e4 steps", "[mbs][ffrf][free]")
{
  // references: conservation laws of an isolated system. The momentum-conserving
  // midpoint scheme (generalised-alpha with rho_inf = 1 drifts by O(h^2): 1e-7 in p and
  // 4e-5 in L at this step, see docs/mbs.md).
  TrussBeamSpec spec;
  spec.dim = 3;
  spec.n_cells = 8;
  spec.n_modes = 6;
  spec.clamped = false;
  spec.bar_stiffness = 200; // first frequencies ~ 300 Hz
  const auto beam = make_truss_beam(spec);
  IntegratorOptions opt;
  opt.scheme = IntegratorOptions::Scheme::momentum_midpoint;
  opt.newton_tolerance = 1e-13;
  MultibodySystem<3> system(opt);
  system.add_body(std::make_unique<FloatingFrameBody<3>>(beam.body));
  auto& body = system.body(0);
  const int m = body.n_modes();
  const double f1 = beam.body.frequencies_hz(0);
  body.set_frame_velocity({0.05, -0.02, 0.01}, {4.0, 1.0, 20.0});
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m), qd = Eigen::VectorXd::Zero(m);
  qd(0) = 2e-3 * 2 * M_PI * f1; // ~ mm amplitude of the first mode
  qd(1) = 1e-3 * 2 * M_PI * f1;
  body.set_modal_state(q, qd);
  const Eigen::Vector3d p0 = body.linear_momentum(), l0 = body.angular_momentum();
  const double e0 = body.kinetic_energy() + body.strain_energy();
  const double h = 1.0 / (f1 * 400);
  double dp = 0, dl = 0, de = 0;
  for (int s = 0; s < 10000; ++s)
  {
    system.step(h);
    dp = std::max(dp, (body.linear_momentum() - p0).norm() / p0.norm());
    dl = std::max(dl, (body.angular_momentum() - l0).norm() / l0.norm());
    de = std::max(de, std::abs(body.kinetic_energy() + body.strain_energy() - e0) / e0);
  }
  WARN("free body f1 " << f1 << " Hz, h " << h << ": max relative drift p " << dp << ", L " << dl
                       << ", E " << de);
  CHECK(dp < 1e-9);
  CHECK(dl < 1e-9);
  CHECK(de < 1e-6);
  CHECK(body.modal_coordinates().norm() > 0);

  // Generalised-alpha, rho_inf = 1, from the same start: energy within 1e-6 as well, the
  // momenta only to O(h^2) (the reason for the midpoint option)
  system.set_options(IntegratorOptions{IntegratorOptions::Scheme::generalized_alpha, 1.0});
  system.reset_accelerations();
  const double e1 = body.kinetic_energy() + body.strain_energy();
  double de_alpha = 0;
  for (int s = 0; s < 10000; ++s)
  {
    system.step(h);
    de_alpha = std::max(de_alpha, std::abs(body.kinetic_energy() + body.strain_energy() - e1) / e1);
  }
  WARN("generalised-alpha rho_inf = 1: max relative energy drift " << de_alpha);
  CHECK(de_alpha < 1e-6);
}

TEST_CASE("Flexible beam spun up about a hinge: the tip lags by the quasi-static coupling load",
          "[mbs][ffrf][spinup]")
{
  // A linear FFRF body has no geometric stiffening: the centrifugal terms
  // -omega^2 tr C(u, psi_k) only soften it (docs/mbs.md), so keep omega << omega_1 here.
  // Reference: the rigid-elastic coupling M_q_theta alpha is the inertia load of the
  // angular acceleration; slowly driven (ramp over 20 periods of mode 1) the modes
  // follow it quasi-statically, q = -K^-1 M_q_theta alpha, and the tip lags behind the
  // frame and behind a rigid beam driven by the same moment.
  TrussBeamSpec spec;
  spec.n_cells = 12;
  spec.n_modes = 4;
  spec.bar_stiffness = 200;
  const auto beam = make_truss_beam(spec);
  IntegratorOptions opt;
  opt.rho_infinity = 0.9;
  MultibodySystem<2> system(opt);
  FloatingFrameOptions fo;
  fo.damping = DampingKind::modal;
  fo.modal_damping_ratio = 0.05;
  const int id = system.add_body(std::make_unique<FloatingFrameBody<2>>(beam.body, fo));
  auto& body = system.body(id);
  system.add_joint(std::make_unique<RevoluteJoint<2>>(Joint<2>::ground, Eigen::Vector2d::Zero(), id,
                                                      Eigen::Vector2d::Zero()));
  const int m = body.n_modes();
  Eigen::MatrixXd mm(3 + m, 3 + m);
  body.mass_matrix(mm);
  const double j_rigid = mm(2, 2); // inertia about the hinge
  const double w1 = 2 * M_PI * beam.body.frequencies_hz(0);
  const double t_ramp = 20 * 2 * M_PI / w1;
  const double moment = 0.02 * j_rigid * w1 * w1 / 400; // alpha ~ w1^2/400 * 0.02 rad
  auto torque = [&](double t)
  { return t < t_ramp ? 0.5 * moment * (1 - std::cos(M_PI * t / t_ramp)) : moment; };
  const double h = t_ramp / 4000;
  const int tip = body.node_set("tip")[0];
  for (int s = 0; s < 4000; ++s)
  {
    body.set_frame_load(Eigen::Vector2d::Zero(),
                        Eigen::Matrix<double, 1, 1>(torque(system.time() + 0.5 * h)));
    system.step(h);
  }
  // rigid beam, same moment: theta = M/(2J) (t^2/2 - (T/pi)^2 (1 - cos(pi t/T))), t <= T
  const double t_end = std::min(system.time(), t_ramp);
  const double rigid_angle =
      moment / (2 * j_rigid) *
      (t_end * t_end / 2 - std::pow(t_ramp / M_PI, 2) * (1 - std::cos(M_PI * t_end / t_ramp)));
  // angular acceleration now (the torque is constant at the end of the ramp)
  const double w0 = body.angular_velocity()(0);
  body.set_frame_load(Eigen::Vector2d::Zero(), Eigen::Matrix<double, 1, 1>(moment));
  const double frame_angle = body.angle();
  const std::vector<double> before = system.save_state();
  system.step(h);
  const double alpha = (body.angular_velocity()(0) - w0) / h;
  body.mass_matrix(mm);
  const Eigen::VectorXd q_qs =
      -beam.body.stiffness_matrix.topLeftCorner(m, m).ldlt().solve(mm.block(3, 2, m, 1) * alpha);
  const Eigen::Vector2d lag_qs = beam.body.psi.middleRows(2 * tip, 2).leftCols(m) * q_qs;
  const Eigen::Vector2d lag = body.rotation().transpose() * body.node_displacement(tip);
  system.restore_state(before); // the tip angle at the end of the ramp
  const Eigen::Vector2d x_tip = body.node_position(tip), x_ref = body.reference_position(tip);
  const double tip_angle =
      std::atan2(x_tip.y(), x_tip.x()) - std::atan2(x_ref.y(), x_ref.x()); // turned by
  WARN("spin-up: tip lag " << lag.y() * 1e3 << " mm (quasi-static " << lag_qs.y() * 1e3
                           << " mm), omega " << w0 << " rad/s vs omega_1 " << w1 << ", tip angle "
                           << tip_angle << " rigid " << rigid_angle << ", frame " << body.angle());
  CHECK(lag.y() < 0);                               // the tip trails the frame
  CHECK(std::abs(lag.y() / lag_qs.y() - 1) < 0.05); // by the coupling load
  CHECK(tip_angle < frame_angle);
  CHECK(tip_angle < rigid_angle); // and the rigid beam
  CHECK(system.constraint_violation() < 1e-12);
}
