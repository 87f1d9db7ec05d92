#pragma once
// A multibody system: floating-frame bodies (rigid bodies are bodies without modes),
// joints (Lagrange multipliers, index 3), force elements and gravity, advanced in time
// by one integrator for every body kind.
//
// Implicit scheme: the generalised-alpha method of Chung & Hulbert (1993) in the
// index-3 constrained Lie-group form of Arnold & Bruels (2007) and Bruels, Cardona &
// Arnold (2012): rotations are updated by exp of a body-frame rotation vector, the
// unknowns of Newton's method are the accelerations and multipliers. The Newton matrix
//     [ M + gamma' D_t + beta' K_t   G^T ]     beta' = h^2 beta (1-af)/(1-am)
//     [ G                            0   ]     gamma' = h gamma (1-af)/(1-am)
// is formed once per step or less often (K_t, D_t: elastic, damping and spring parts; the
// derivatives of the quadratic velocity vector and of G^T lambda are left out, so Newton converges
// linearly for fast rotation) and reused across the iterations. A linear system (bodies
// clamped to ground, no joints) is solved exactly in one iteration with a factorisation
// kept across steps. rho_infinity = 1 has no numerical dissipation (the trapezoidal
// rule); smaller values damp the highest modes, so the step is not limited by them.
//
// Explicit option: semi-implicit (symplectic) Euler with the constraints projected back
// onto position and velocity level each step; stable only below 2/omega_max.
//
// Momentum-conserving option (free bodies without joints or force elements, e.g. chips):
// implicit midpoint rule whose frame equations are written as discrete balances of
// linear and angular momentum, (p1 - p0)/h = F_mid, (L1 - L0)/h = M_mid (Simo & Tarnow
// 1992 do the same for their energy-momentum scheme), so momenta are conserved to the
// Newton tolerance; modal rows: M(q_mid)(v1 - v0)/h = f(mid). Newton matrix by finite
// differences once per step.
//
// Sub-stepping within a fluid step: set skin forces once, then call step(dt) as often as
// needed; loads are held constant.

#include "mbs/force_element.h"
#include "mbs/joint.h"

#include <Eigen/Dense>
#include <memory>
#include <vector>

namespace chipflex::mbs
{
struct IntegratorOptions
{
  enum class Scheme
  {
    generalized_alpha,
    symplectic_euler,
    momentum_midpoint
  };
  Scheme scheme = Scheme::generalized_alpha;
  double rho_infinity = 0.9;       ///< spectral radius at infinite frequency, 0..1
  double newton_tolerance = 1e-10; ///< on the acceleration correction, relative
  int max_newton_iterations = 50;
  /// Keep the Newton matrix across steps of equal size while Newton converges in a few
  /// iterations (refactorised when it needs more); the residual is always exact, so this
  /// changes the convergence rate only, never the solution.
  bool reuse_newton_matrix = true;
};

template <int dim>
class MultibodySystem
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;

  explicit MultibodySystem(const IntegratorOptions& options = {});

  /// Adds a body; returns its index. Bodies are owned by the system.
  int add_body(std::unique_ptr<FloatingFrameBody<dim>> body);
  int add_joint(std::unique_ptr<Joint<dim>> joint);
  int add_force_element(std::unique_ptr<ForceElement<dim>> element);
  void set_gravity(const Vector& g) { gravity_ = g; }
  /// The bodies move in a turning reference frame (positions and velocities relative to
  /// it): each feels its fictitious forces. Not with the momentum midpoint scheme.
  void set_rotating_frame(const RotatingFrame& frame);
  void set_options(const IntegratorOptions& options);
  const IntegratorOptions& options() const { return options_; }

  int n_bodies() const { return static_cast<int>(bodies_.size()); }
  FloatingFrameBody<dim>& body(int i) { return *bodies_[i]; }
  const FloatingFrameBody<dim>& body(int i) const { return *bodies_[i]; }
  const Joint<dim>& joint(int i) const { return *joints_[i]; }
  const ForceElement<dim>& force_element(int i) const { return *elements_[i]; }
  BodyView<dim> view(int body) const;

  /// Advances by dt (loads held). Throws SimulationError if Newton fails.
  void step(double dt);
  double time() const { return time_; }
  void set_time(double t) { time_ = t; }
  int last_newton_iterations() const { return last_iterations_; }
  /// Max |g| of the joint equations in the current state.
  double constraint_violation();
  /// Forgets the stored accelerations: call after changing the state by hand
  /// (velocities, poses, modal state); the next step starts from consistent ones.
  void reset_accelerations() { initialized_ = false; }

  /// Checkpoint: time, body states, integrator history (accelerations, multipliers).
  std::vector<double> save_state() const;
  /// Restores a save_state() of a system built the same way (InputError otherwise).
  void restore_state(const std::vector<double>& state);

private:
  void setup();
  void assemble_mass_matrix();
  void assemble_forces();
  void assemble_constraints();
  void scatter(const Eigen::VectorXd& increment, const Eigen::VectorXd& v);
  void initialize_accelerations();
  void factorize_kkt(double c_k, double c_d, bool with_tangent);
  void step_generalized_alpha(double h);
  void step_symplectic_euler(double h);
  void step_momentum_midpoint(double h);
  void midpoint_residual(double h, const Eigen::VectorXd& v1, Eigen::VectorXd& r);
  void momenta(Eigen::VectorXd& out); ///< frame rows: [p; L] (world), from m_ and state
  void project_constraints();

  IntegratorOptions options_;
  std::vector<std::unique_ptr<FloatingFrameBody<dim>>> bodies_;
  std::vector<std::unique_ptr<Joint<dim>>> joints_;
  std::vector<std::unique_ptr<ForceElement<dim>>> elements_;
  Vector gravity_ = Vector::Zero();
  double time_ = 0;
  RotatingFrame frame_;
  double force_time_ = 0; ///< the time assemble_forces() evaluates time-dependent loads at

  // layout
  std::vector<int> offsets_, joint_rows_;
  int nv_ = -1, nc_ = -1;
  bool linear_ = false;

  // integrator state
  bool initialized_ = false;
  Eigen::VectorXd a_, abar_, lambda_;
  int last_iterations_ = 0;
  double factored_h_ = -1; ///< step of the kept factorisation (-1: none)
  bool refactor_next_ = true;

  // preallocated work space (no allocation inside step() once set up)
  Eigen::MatrixXd m_, g_jac_, kkt_;
  Eigen::VectorXd f_, g_, rhs_, sol_, vn_, v1_, a1_, abar1_, incr_, delta_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  Eigen::VectorXd mom0_, mom1_, res_, res2_, vmid_;
};
} // namespace chipflex::mbs
