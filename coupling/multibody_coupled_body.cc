#include "coupling/multibody_coupled_body.h"

#include <algorithm>
#include <cmath>

namespace chipflex::coupling
{
template <int dim>
MultibodyCoupledBody<dim>::MultibodyCoupledBody(std::string kind,
                                                std::unique_ptr<mbs::MultibodySystem<dim>> system,
                                                mbs::SkinBody<dim>& skin, double max_step,
                                                Probe probe)
    : kind_(std::move(kind)), system_(std::move(system)), skin_(&skin), max_step_(max_step),
      probe_(std::move(probe))
{
}

template <int dim>
MultibodyCoupledBody<dim>::MultibodyCoupledBody(std::string kind,
                                                std::unique_ptr<mbs::MultibodySystem<dim>> system,
                                                std::unique_ptr<mbs::SkinBody<dim>> owned_skin,
                                                double max_step, Probe probe)
    : kind_(std::move(kind)), system_(std::move(system)), owned_skin_(std::move(owned_skin)),
      skin_(owned_skin_.get()), max_step_(max_step), probe_(std::move(probe))
{
}

template <int dim>
void MultibodyCoupledBody<dim>::advance(double dt)
{
  if (dt <= 0)
    return;
  const int n = max_step_ > 0 ? std::max(1, static_cast<int>(std::ceil(dt / max_step_ - 1e-9))) : 1;
  for (int k = 0; k < n; ++k)
    system_->step(dt / n);
  steps_ += n;
}

template <int dim>
typename MultibodyCoupledBody<dim>::Vector MultibodyCoupledBody<dim>::linear_momentum() const
{
  Vector p = Vector::Zero();
  for (int i = 0; i < system_->n_bodies(); ++i)
    p += system_->body(i).linear_momentum();
  return p;
}

template <int dim>
double MultibodyCoupledBody<dim>::contact_lead(double dt) const
{
  const int n = max_step_ > 0 ? std::max(1, static_cast<int>(std::ceil(dt / max_step_ - 1e-9))) : 1;
  const auto& o = system_->options();
  switch (o.scheme)
  {
  case mbs::IntegratorOptions::Scheme::symplectic_euler:
    // x1 = x + dt v + c dt^2 a with c = (n + 1) / 2n under a held load: a spring
    // sampled at x + lead dt v keeps det = 1 for lead = 1 - c.
    return (n - 1) / (2.0 * n);
  case mbs::IntegratorOptions::Scheme::generalized_alpha:
  {
    // Chung & Hulbert's parameters from rho_infinity (as MultibodySystem::step).
    const double rho = o.rho_infinity;
    const double am = (2 * rho - 1) / (rho + 1), af = rho / (rho + 1);
    const double gamma = 0.5 + af - am;
    return 0.5 + (1 - gamma) / n;
  }
  case mbs::IntegratorOptions::Scheme::momentum_midpoint:
    return 0.5;
  }
  return 0.5;
}

template <int dim>
double MultibodyCoupledBody<dim>::mass() const
{
  double m = 0;
  for (int i = 0; i < system_->n_bodies(); ++i)
    m += system_->body(i).mass();
  return m;
}

template <int dim>
typename MultibodyCoupledBody<dim>::Vector MultibodyCoupledBody<dim>::probe_position() const
{
  if (probe_)
    return probe_(*system_);
  return system_->body(0).position();
}

template <int dim>
Eigen::Matrix<double, dim, dim> MultibodyCoupledBody<dim>::frame_rotation() const
{
  return system_->body(0).rotation();
}

template <int dim>
double MultibodyCoupledBody<dim>::max_deflection() const
{
  const auto& body = system_->body(0);
  if (body.n_modes() == 0)
    return 0;
  double largest = 0;
  for (int node : body.skin_node_ids())
    largest = std::max(largest, body.node_displacement(node).norm());
  return largest;
}

template <int dim>
double MultibodyCoupledBody<dim>::strain_energy() const
{
  double e = 0;
  for (int i = 0; i < system_->n_bodies(); ++i)
    e += system_->body(i).strain_energy();
  return e;
}

template <int dim>
void MultibodyCoupledBody<dim>::place(double t, const Vector& position,
                                      const Eigen::Matrix<double, dim, dim>& rotation,
                                      const Vector& velocity,
                                      const Eigen::Vector3d& angular_velocity)
{
  if (system_->n_bodies() != 1 || system_->body(0).clamped_to_ground())
    throw InputError("chip source",
                     "a " + kind_ + " body of several parts or clamped cannot be released");
  auto& body = system_->body(0);
  body.set_pose(position, rotation);
  Eigen::Matrix<double, mbs::rotation_dofs<dim>, 1> omega;
  if constexpr (dim == 2)
    omega[0] = angular_velocity.z();
  else
    omega = rotation.transpose() * angular_velocity; // the body frame's
  body.set_frame_velocity(velocity, omega);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(body.n_modes());
  body.set_modal_state(zero, zero);
  system_->reset_accelerations();
  system_->set_time(t); // its time-dependent loads (a frame spinning up) at the run's time
}

template class MultibodyCoupledBody<2>;
template class MultibodyCoupledBody<3>;
} // namespace chipflex::coupling
