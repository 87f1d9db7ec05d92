#include "mbs/multibody_system.h"

#include "common/input_error.h"

#include <cmath>
#include <string>

namespace chipflex::mbs
{
template <int dim>
MultibodySystem<dim>::MultibodySystem(const IntegratorOptions& options)
{
  set_options(options);
}

template <int dim>
void MultibodySystem<dim>::set_options(const IntegratorOptions& options)
{
  if (!(options.rho_infinity >= 0 && options.rho_infinity <= 1))
    throw InputError("integrator rho_infinity", "must lie in [0, 1]");
  if (options.max_newton_iterations < 1 || !(options.newton_tolerance > 0))
    throw InputError("integrator Newton options", "need >= 1 iteration and a positive tolerance");
  options_ = options;
  factored_h_ = -1;
  refactor_next_ = true;
}

template <int dim>
void MultibodySystem<dim>::set_rotating_frame(const RotatingFrame& frame)
{
  if (dim == 2 && frame.active() && frame.angular_velocity.head<2>().norm() > 0)
    throw InputError("rotating frame, angular velocity", "a 2D frame turns about z only");
  if (frame.active() && options_.scheme == IntegratorOptions::Scheme::momentum_midpoint)
    throw InputError("integrator scheme momentum_midpoint",
                     "conserves the momenta of an inertial frame: not in a turning frame");
  frame_ = frame;
  nv_ = -1; // setup() again: the forces now depend on the state
}

template <int dim>
int MultibodySystem<dim>::add_body(std::unique_ptr<FloatingFrameBody<dim>> body)
{
  bodies_.push_back(std::move(body));
  nv_ = -1;
  return n_bodies() - 1;
}

template <int dim>
int MultibodySystem<dim>::add_joint(std::unique_ptr<Joint<dim>> joint)
{
  if (joint->body_a() >= n_bodies() || joint->body_b() >= n_bodies() || joint->body_a() < -1 ||
      joint->body_b() < -1)
    throw InputError("joint", "refers to a body that is not in the system");
  joints_.push_back(std::move(joint));
  nv_ = -1;
  return static_cast<int>(joints_.size()) - 1;
}

template <int dim>
int MultibodySystem<dim>::add_force_element(std::unique_ptr<ForceElement<dim>> element)
{
  if (element->body_a() >= n_bodies() || element->body_b() >= n_bodies() ||
      element->body_a() < -1 || element->body_b() < -1)
    throw InputError("force element", "refers to a body that is not in the system");
  elements_.push_back(std::move(element));
  nv_ = -1;
  return static_cast<int>(elements_.size()) - 1;
}

template <int dim>
BodyView<dim> MultibodySystem<dim>::view(int body) const
{
  if (body < 0)
    return {};
  return {bodies_[body].get(), offsets_[body]};
}

template <int dim>
void MultibodySystem<dim>::setup()
{
  // Cheap to check every step: bodies may be clamped between construction and the
  // first step, which changes their number of velocities.
  int nv = 0, nc = 0;
  for (const auto& b : bodies_)
    nv += b->n_velocities();
  for (const auto& j : joints_)
    nc += j->n_equations();
  if (nv == nv_ && nc == nc_ && static_cast<int>(offsets_.size()) == n_bodies())
    return;
  offsets_.clear();
  int off = 0;
  for (const auto& b : bodies_)
  {
    offsets_.push_back(off);
    off += b->n_velocities();
  }
  joint_rows_.clear();
  int row = 0;
  for (const auto& j : joints_)
  {
    joint_rows_.push_back(row);
    row += j->n_equations();
  }
  nv_ = nv;
  nc_ = nc;
  linear_ = nc == 0 && !frame_.active();
  for (const auto& b : bodies_)
    linear_ = linear_ && b->linear();
  m_.setZero(nv, nv);
  g_jac_.setZero(nc, nv);
  kkt_.setZero(nv + nc, nv + nc);
  lu_ = Eigen::PartialPivLU<Eigen::MatrixXd>(nv + nc);
  for (Eigen::VectorXd* v : {&f_, &vn_, &v1_, &a1_, &abar1_, &incr_, &a_, &abar_})
    v->setZero(nv);
  g_.setZero(nc);
  lambda_.setZero(nc);
  rhs_.setZero(nv + nc);
  sol_.setZero(nv + nc);
  delta_.setZero(nv);
  initialized_ = false;
  factored_h_ = -1;
}

template <int dim>
void MultibodySystem<dim>::assemble_mass_matrix()
{
  for (int i = 0; i < n_bodies(); ++i)
  {
    const int n = bodies_[i]->n_velocities();
    bodies_[i]->mass_matrix(m_.block(offsets_[i], offsets_[i], n, n));
  }
}

template <int dim>
void MultibodySystem<dim>::assemble_forces()
{
  for (int i = 0; i < n_bodies(); ++i)
  {
    const auto f = f_.segment(offsets_[i], bodies_[i]->n_velocities());
    bodies_[i]->forces(gravity_, f);
    if (frame_.active())
      bodies_[i]->add_frame_inertia(frame_, force_time_, f);
  }
  for (const auto& e : elements_)
    e->add_forces(view(e->body_a()), view(e->body_b()), f_);
}

template <int dim>
void MultibodySystem<dim>::assemble_constraints()
{
  g_jac_.setZero();
  for (std::size_t j = 0; j < joints_.size(); ++j)
  {
    const int ne = joints_[j]->n_equations();
    joints_[j]->evaluate(view(joints_[j]->body_a()), view(joints_[j]->body_b()),
                         g_.segment(joint_rows_[j], ne), g_jac_.middleRows(joint_rows_[j], ne));
  }
}

template <int dim>
void MultibodySystem<dim>::scatter(const Eigen::VectorXd& increment, const Eigen::VectorXd& v)
{
  for (int i = 0; i < n_bodies(); ++i)
  {
    const int n = bodies_[i]->n_velocities();
    bodies_[i]->set_from_base(increment.segment(offsets_[i], n));
    bodies_[i]->set_velocities(v.segment(offsets_[i], n));
  }
}

template <int dim>
void MultibodySystem<dim>::factorize_kkt(double c_k, double c_d, bool with_tangent)
{
  factored_h_ = -1; // the caller marks a kept generalised-alpha matrix
  kkt_.topLeftCorner(nv_, nv_) = m_;
  if (with_tangent)
  {
    for (int i = 0; i < n_bodies(); ++i)
    {
      const int n = bodies_[i]->n_velocities();
      bodies_[i]->add_tangent(c_k, c_d, kkt_.block(offsets_[i], offsets_[i], n, n));
    }
    for (const auto& e : elements_)
      e->add_tangent(view(e->body_a()), view(e->body_b()), c_k, c_d, kkt_.topLeftCorner(nv_, nv_));
  }
  kkt_.topRightCorner(nv_, nc_) = g_jac_.transpose();
  kkt_.bottomLeftCorner(nc_, nv_) = g_jac_;
  kkt_.bottomRightCorner(nc_, nc_).setZero();
  lu_.compute(kkt_);
}

template <int dim>
void MultibodySystem<dim>::initialize_accelerations()
{
  // Accelerations consistent with the current state: [M G^T; G 0] [a; lambda] = [f; 0]
  // (the velocity-dependent constraint term is omitted; the index-3 iteration corrects it).
  for (auto& b : bodies_)
    b->store_base();
  assemble_mass_matrix();
  force_time_ = time_;
  assemble_forces();
  if (nc_ > 0)
    assemble_constraints();
  factorize_kkt(0, 0, false);
  rhs_.head(nv_) = f_;
  rhs_.tail(nc_).setZero();
  sol_ = lu_.solve(rhs_);
  a_ = sol_.head(nv_);
  abar_ = a_;
  lambda_ = sol_.tail(nc_);
  initialized_ = true;
  factored_h_ = -1;
}

template <int dim>
void MultibodySystem<dim>::step(double dt)
{
  if (!(dt > 0))
    throw InputError("MultibodySystem::step", "time step must be positive");
  setup();
  if (nv_ == 0) // every body fixed (a clamped rigid body): nothing moves
  {
    time_ += dt;
    return;
  }
  if (!initialized_)
    initialize_accelerations();
  switch (options_.scheme)
  {
  case IntegratorOptions::Scheme::generalized_alpha:
    step_generalized_alpha(dt);
    break;
  case IntegratorOptions::Scheme::symplectic_euler:
    step_symplectic_euler(dt);
    break;
  case IntegratorOptions::Scheme::momentum_midpoint:
    step_momentum_midpoint(dt);
    break;
  }
  time_ += dt;
}

template <int dim>
void MultibodySystem<dim>::step_generalized_alpha(double h)
{
  const double rho = options_.rho_infinity;
  const double am = (2 * rho - 1) / (rho + 1), af = rho / (rho + 1);
  const double gamma = 0.5 + af - am, beta = 0.25 * (gamma + 0.5) * (gamma + 0.5);
  const double beta_p = h * h * beta * (1 - af) / (1 - am);
  const double gamma_p = h * gamma * (1 - af) / (1 - am);

  for (int i = 0; i < n_bodies(); ++i)
  {
    bodies_[i]->store_base();
    vn_.segment(offsets_[i], bodies_[i]->n_velocities()) = bodies_[i]->velocities();
  }
  a1_ = a_;
  // A kept matrix must be for this step size; a nonlinear system refactorises when the
  // last step needed many iterations (the matrix has gone stale) or reuse is off.
  bool refactor =
      factored_h_ != h || (!linear_ && (refactor_next_ || !options_.reuse_newton_matrix));
  bool fresh = refactor;
  auto update_kinematics = [&]()
  {
    abar1_ = ((1 - af) * a1_ + af * a_ - am * abar_) / (1 - am);
    v1_ = vn_ + h * ((1 - gamma) * abar_ + gamma * abar1_);
    incr_ = h * vn_ + (h * h * (0.5 - beta)) * abar_ + (h * h * beta) * abar1_;
    scatter(incr_, v1_);
  };
  constexpr int stale_limit = 4; // iterations a kept matrix may need before it is renewed
  force_time_ = time_ + h;       // the iterate is the state at the end of the step
  int it = 0;
  double last_correction = 0;
  for (;; ++it)
  {
    if (it == options_.max_newton_iterations)
      throw SimulationError("mbs: Newton did not converge at t = " + std::to_string(time_) +
                            " s (step " + std::to_string(h) + " s); reduce the step");
    update_kinematics();
    if (!linear_ || refactor)
      assemble_mass_matrix();
    assemble_forces();
    if (nc_ > 0)
      assemble_constraints();
    rhs_.head(nv_) = f_;
    rhs_.head(nv_).noalias() -= m_ * a1_;
    // acceleration scale of the Newton test: the largest force term over its mass, so
    // that a body at rest (a = 0) under balanced loads still has a meaningful tolerance
    double scale = std::max(a1_.cwiseAbs().maxCoeff(), 1e-12);
    for (int i = 0; i < nv_; ++i)
      scale = std::max(scale, std::abs(f_(i)) / m_(i, i));
    if (nc_ > 0)
    {
      delta_.noalias() = g_jac_.transpose() * lambda_;
      for (int i = 0; i < nv_; ++i)
        scale = std::max(scale, std::abs(delta_(i)) / m_(i, i));
      rhs_.head(nv_) -= delta_;
      rhs_.tail(nc_) = -g_ / beta_p;
    }
    if (!fresh && it == stale_limit)
      refactor = true; // the kept matrix converges too slowly: refresh it at this iterate
    if (refactor)
    {
      factorize_kkt(beta_p, gamma_p, true);
      factored_h_ = h;
      refactor = false;
      fresh = true;
    }
    sol_ = lu_.solve(rhs_);
    a1_ += sol_.head(nv_);
    lambda_ += sol_.tail(nc_);
    if (linear_) // exact tangent of a linear system: one iteration solves it
      break;
    const double correction = sol_.head(nv_).cwiseAbs().maxCoeff();
    if (correction <= options_.newton_tolerance * scale)
      break;
    // round-off floor: a correction that no longer shrinks, already tiny, is converged
    if (correction <= 1e-8 * scale && correction >= 0.5 * last_correction)
      break;
    // a matrix that does not contract (strongly nonlinear elastic forces within the step,
    // e.g. a St Venant-Kirchhoff body far from equilibrium) is renewed at this iterate
    if (it > 0 && correction > 0.5 * last_correction)
      refactor = true;
    last_correction = correction;
  }
  update_kinematics();
  last_iterations_ = it + 1;
  refactor_next_ = last_iterations_ > stale_limit;
  a_ = a1_;
  abar_ = abar1_;
}

template <int dim>
void MultibodySystem<dim>::step_symplectic_euler(double h)
{
  for (int i = 0; i < n_bodies(); ++i)
  {
    bodies_[i]->store_base();
    vn_.segment(offsets_[i], bodies_[i]->n_velocities()) = bodies_[i]->velocities();
  }
  assemble_mass_matrix();
  force_time_ = time_;
  assemble_forces();
  if (nc_ > 0)
    assemble_constraints();
  factorize_kkt(0, 0, false);
  rhs_.head(nv_) = f_;
  rhs_.tail(nc_).setZero();
  sol_ = lu_.solve(rhs_);
  a_ = sol_.head(nv_);
  abar_ = a_;
  v1_ = vn_ + h * a_;
  incr_ = h * v1_;
  scatter(incr_, v1_);
  if (nc_ > 0)
    project_constraints();
  last_iterations_ = 1;
}

template <int dim>
void MultibodySystem<dim>::momenta(Eigen::VectorXd& out)
{
  // p = (M v)_R, L = R x p + A (M v)_theta: the frame rows of M v are the momenta about
  // the frame origin in body axes (see FloatingFrameBody::angular_momentum)
  for (int i = 0; i < n_bodies(); ++i)
  {
    const auto& b = *bodies_[i];
    if (b.clamped_to_ground())
      continue;
    const int o = offsets_[i], n = b.n_velocities();
    constexpr int r = rotation_dofs<dim>;
    const Eigen::Matrix<double, dim + r, 1> mv = m_.block(o, o, dim + r, n) * b.velocities();
    const Vector p = mv.template head<dim>();
    out.template segment<dim>(o) = p;
    if constexpr (dim == 2)
      out(o + 2) = cross(b.position(), p) + mv(2);
    else
      out.template segment<3>(o + 3) = b.position().cross(p) + b.rotation() * mv.template tail<3>();
  }
}

template <int dim>
void MultibodySystem<dim>::midpoint_residual(double h, const Eigen::VectorXd& v1,
                                             Eigen::VectorXd& r)
{
  constexpr int rd = rotation_dofs<dim>;
  incr_ = (0.5 * h) * (vn_ + v1);
  vmid_ = 0.5 * (vn_ + v1);
  delta_ = 0.5 * incr_;
  scatter(delta_, vmid_); // midpoint state
  assemble_mass_matrix();
  assemble_forces();
  r.noalias() = m_ * (v1 - vn_) / h;
  r -= f_; // modal rows final; frame rows replaced below
  for (int i = 0; i < n_bodies(); ++i)
    if (!bodies_[i]->clamped_to_ground())
    {
      Vector force;
      Eigen::Matrix<double, rd, 1> moment;
      bodies_[i]->applied_frame_load(gravity_, force, moment);
      r.template segment<dim>(offsets_[i]) = -force;
      r.template segment<rd>(offsets_[i] + dim) = -moment;
    }
  scatter(incr_, v1); // end state
  assemble_mass_matrix();
  momenta(mom1_);
  for (int i = 0; i < n_bodies(); ++i)
    if (!bodies_[i]->clamped_to_ground())
      r.segment(offsets_[i], dim + rd) +=
          (mom1_.segment(offsets_[i], dim + rd) - mom0_.segment(offsets_[i], dim + rd)) / h;
}

template <int dim>
void MultibodySystem<dim>::step_momentum_midpoint(double h)
{
  if (nc_ > 0 || !elements_.empty())
    throw InputError("integrator scheme momentum_midpoint",
                     "only for bodies without joints or force elements");
  if (frame_.active())
    throw InputError("integrator scheme momentum_midpoint",
                     "conserves the momenta of an inertial frame: not in a turning frame");
  mom0_.setZero(nv_);
  mom1_.setZero(nv_);
  res_.resize(nv_);
  res2_.resize(nv_);
  vmid_.resize(nv_);
  for (int i = 0; i < n_bodies(); ++i)
  {
    bodies_[i]->store_base();
    vn_.segment(offsets_[i], bodies_[i]->n_velocities()) = bodies_[i]->velocities();
  }
  assemble_mass_matrix();
  momenta(mom0_);
  // predictor from the last accelerations; Newton matrix by forward differences
  v1_ = vn_ + h * a_;
  midpoint_residual(h, v1_, res_);
  Eigen::MatrixXd& jac = kkt_; // nc = 0: same size
  for (int j = 0; j < nv_; ++j)
  {
    const double eps = 1e-7 * (1 + std::abs(v1_(j)));
    a1_ = v1_;
    a1_(j) += eps;
    midpoint_residual(h, a1_, res2_);
    jac.col(j) = (res2_ - res_) / eps;
  }
  lu_.compute(jac);
  int it = 0;
  double last_correction = 0;
  for (;; ++it)
  {
    if (it == options_.max_newton_iterations)
      throw SimulationError(
          "mbs: midpoint Newton did not converge at t = " + std::to_string(time_) + " s");
    if (it > 0)
      midpoint_residual(h, v1_, res_);
    sol_ = lu_.solve(res_);
    v1_ -= sol_;
    const double correction = sol_.cwiseAbs().maxCoeff();
    const double scale = std::max(v1_.cwiseAbs().maxCoeff(), 1e-12);
    if (correction <= options_.newton_tolerance * scale ||
        (correction <= 1e-8 * scale && correction >= 0.5 * last_correction))
      break;
    last_correction = correction;
  }
  incr_ = (0.5 * h) * (vn_ + v1_);
  scatter(incr_, v1_);
  a_ = (v1_ - vn_) / h;
  abar_ = a_;
  last_iterations_ = it + 1;
  factored_h_ = -1;
}

template <int dim>
void MultibodySystem<dim>::project_constraints()
{
  // Position projection (M-orthogonal, Newton on g = 0), then velocity projection onto
  // G v = 0; this removes the drift of the explicit scheme.
  for (int it = 0; it < 5; ++it)
  {
    assemble_constraints();
    if (g_.cwiseAbs().maxCoeff() < 1e-13)
      break;
    assemble_mass_matrix();
    factorize_kkt(0, 0, false);
    rhs_.head(nv_).setZero();
    rhs_.tail(nc_) = -g_;
    sol_ = lu_.solve(rhs_);
    incr_ += sol_.head(nv_);
    scatter(incr_, v1_);
  }
  assemble_mass_matrix();
  assemble_constraints();
  factorize_kkt(0, 0, false);
  rhs_.head(nv_).setZero();
  rhs_.tail(nc_) = -g_jac_ * v1_;
  sol_ = lu_.solve(rhs_);
  v1_ += sol_.head(nv_);
  scatter(incr_, v1_);
}

template <int dim>
double MultibodySystem<dim>::constraint_violation()
{
  setup();
  if (nc_ == 0)
    return 0;
  assemble_constraints();
  return g_.cwiseAbs().maxCoeff();
}

template <int dim>
std::vector<double> MultibodySystem<dim>::save_state() const
{
  std::vector<double> s = {static_cast<double>(nv_), static_cast<double>(nc_), time_,
                           initialized_ ? 1.0 : 0.0};
  for (const auto& b : bodies_)
    b->save_state(s);
  for (const Eigen::VectorXd* v : {&a_, &abar_, &lambda_})
    s.insert(s.end(), v->data(), v->data() + v->size());
  return s;
}

template <int dim>
void MultibodySystem<dim>::restore_state(const std::vector<double>& s)
{
  setup();
  std::vector<double> probe;
  for (const auto& b : bodies_)
    b->save_state(probe);
  // A state saved before the first step (the system not yet laid out) has no integrator
  // history: the accelerations start afresh from it.
  const bool fresh = s.size() == 4 + probe.size() && static_cast<int>(s[0]) == -1;
  if (fresh)
  {
    time_ = s[2];
    const double* p = s.data() + 4;
    for (auto& b : bodies_)
      p = b->restore_state(p);
    for (Eigen::VectorXd* v : {&a_, &abar_, &lambda_})
      v->setZero();
    initialized_ = false;
    factored_h_ = -1;
    return;
  }
  const std::size_t expected = 4 + probe.size() + 2 * nv_ + nc_;
  if (s.size() != expected || static_cast<int>(s[0]) != nv_ || static_cast<int>(s[1]) != nc_)
    throw InputError("multibody checkpoint", "state of " + std::to_string(s.size()) +
                                                 " values does not fit this system (" +
                                                 std::to_string(expected) + ")");
  time_ = s[2];
  initialized_ = s[3] != 0;
  const double* p = s.data() + 4;
  for (auto& b : bodies_)
    p = b->restore_state(p);
  for (Eigen::VectorXd* v : {&a_, &abar_, &lambda_})
  {
    *v = Eigen::Map<const Eigen::VectorXd>(p, v->size());
    p += v->size();
  }
  factored_h_ = -1;
}

template class MultibodySystem<2>;
template class MultibodySystem<3>;
} // namespace chipflex::mbs
