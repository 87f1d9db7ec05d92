#include "coupling/multibody_coupled_body.h"

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

template class MultibodyCoupledBody<2>;
template class MultibodyCoupledBody<3>;
} // namespace chipflex::coupling
