#include "coupling/contact_simulation.h"

namespace chipflex::coupling
{
template <int dim>
int ContactSimulation<dim>::add_wall(const sph::WallSurface<dim>& wall)
{
  walls_.push_back(std::make_unique<sph::WallSurface<dim>>(wall));
  auto& w = *walls_.back();
  if (w.velocities.size() != w.vertices.size())
    w.velocities.assign(w.vertices.size(), Vector::Zero());
  contact_.add_obstacle(w);
  return int(walls_.size()) - 1;
}

template <int dim>
int ContactSimulation<dim>::add_body(CoupledBody<dim>& body, const std::string& name)
{
  contact_.add_body(body.skin(), body.mass(), name,
                    [&body](double dt) { return body.contact_lead(dt); });
  bodies_.push_back(&body);
  return int(bodies_.size()) - 1;
}

template <int dim>
void ContactSimulation<dim>::step(double dt)
{
  contact_.compute(dt);
  for (std::size_t b = 0; b < bodies_.size(); ++b)
  {
    bodies_[b]->skin().set_skin_forces(contact_.body_forces(int(b)));
    bodies_[b]->advance(dt);
  }
  time_ += dt;
}

template <int dim>
typename ContactSimulation<dim>::Vector ContactSimulation<dim>::total_momentum() const
{
  Vector p = Vector::Zero();
  for (const auto* b : bodies_)
    p += b->linear_momentum();
  return p;
}

template class ContactSimulation<2>;
template class ContactSimulation<3>;
} // namespace chipflex::coupling
