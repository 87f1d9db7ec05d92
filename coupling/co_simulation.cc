#include "coupling/co_simulation.h"

#include "common/hdf5_file.h"
#include "common/input_error.h"
#include "sph/lennard_jones_wall.h"

#include <cmath>

namespace chipflex::coupling
{
template <int dim>
CoSimulation<dim>::CoSimulation(sph::FluidSolver<dim>& fluid) : fluid_(fluid)
{
  fluid_.add_hook(sph::HookPoint::before_forces,
                  [this](sph::FluidSolver<dim>&) { publish_skins(); });
  fluid_.add_hook(sph::HookPoint::after_step,
                  [this](sph::FluidSolver<dim>&) { exchange_and_advance(); });
}

template <int dim>
int CoSimulation<dim>::add_body(CoupledBody<dim>& body, const std::string& name,
                                sph::WallModel model, sph::LennardJonesParameters lennard_jones,
                                double expected_pressure)
{
  if (fluid_.step_count() > 0)
    throw std::logic_error("CoSimulation::add_body after the first step");
  for (const auto& c : bodies_)
    if (c.name == name)
      throw InputError("body '" + name + "'", "a body of that name exists already");
  const auto& p = fluid_.parameters();
  if (model == sph::WallModel::lennard_jones)
  {
    const double c0 = p.speed_of_sound;
    const double pe =
        expected_pressure > 0 ? expected_pressure : p.reference_density * (c0 / 10) * (c0 / 10);
    lennard_jones =
        sph::derive_lennard_jones(lennard_jones, p.particle_spacing, p.reference_density, pe, name);
  }
  Coupled c;
  c.body = &body;
  c.name = name;
  c.wall = std::make_unique<SkinWall<dim>>(body.skin(), name, model, lennard_jones);
  c.wall_id = fluid_.add_wall(c.wall->surface());
  bodies_.push_back(std::move(c));
  return static_cast<int>(bodies_.size()) - 1;
}

template <int dim>
void CoSimulation<dim>::enable_contact(const ContactParameters& parameters)
{
  if (fluid_.step_count() > 0)
    throw std::logic_error("CoSimulation::enable_contact after the first step");
  // The fluid's walls no longer change address once it has its first step's set-up
  // (walls are added before it), and move_wall updates them in place.
  fluid_.initialise();
  contact_ = std::make_unique<ContactModel<dim>>(parameters);
  for (int w = 0; w < fluid_.n_walls(); ++w)
  {
    bool skin = false;
    for (const auto& c : bodies_)
      skin = skin || c.wall_id == w;
    if (!skin)
      contact_->add_obstacle(fluid_.wall(w));
  }
  // A body of infinite mass (a wall with a prescribed motion) is an obstacle that moves.
  for (auto& c : bodies_)
  {
    CoupledBody<dim>* body = c.body;
    if (std::isnan(body->mass()))
      throw InputError("body '" + c.name + "'",
                       "its mass is unknown (an FMU body), so it cannot take part in contact");
    if (std::isfinite(body->mass()))
    {
      c.contact_id = contact_->add_body(body->skin(), body->mass(), c.name,
                                        [body](double dt) { return body->contact_lead(dt); });
      contact_->set_active(c.contact_id, !c.parked);
    }
    else
      contact_->add_obstacle(fluid_.wall(c.wall_id));
  }
}

template <int dim>
void CoSimulation<dim>::publish_skins()
{
  for (auto& c : bodies_)
  {
    c.wall->publish();
    fluid_.move_wall(c.wall_id, c.wall->surface().vertices, c.wall->surface().velocities);
  }
}

template <int dim>
void CoSimulation<dim>::exchange_and_advance()
{
  const double dt = fluid_.last_time_step();
  // Every body's contact forces come from the state at t, before any body advances.
  if (contact_)
    contact_->compute(dt);
  for (std::size_t b = 0; b < bodies_.size(); ++b)
  {
    auto& c = bodies_[b];
    if (c.parked)
      continue;
    if (contact_ && c.contact_id >= 0)
      c.wall->deliver(fluid_.wall_vertex_forces(c.wall_id), &contact_->body_forces(c.contact_id));
    else
      c.wall->deliver(fluid_.wall_vertex_forces(c.wall_id));
    c.body->advance(dt);
  }
}

template <int dim>
void CoSimulation<dim>::set_parked(int b, bool parked)
{
  auto& c = bodies_.at(b);
  c.parked = parked;
  if (contact_ && c.contact_id >= 0)
    contact_->set_active(c.contact_id, !parked);
}

template <int dim>
double CoSimulation<dim>::step()
{
  return fluid_.step();
}

template <int dim>
typename CoSimulation<dim>::Vector CoSimulation<dim>::fluid_momentum() const
{
  const auto& p = fluid_.particles();
  Vector sum = Vector::Zero();
  for (std::size_t i = p.n_boundary; i < p.size(); ++i)
    for (int d = 0; d < dim; ++d)
      sum[d] += p.velocity[d][i];
  return fluid_.particle_mass() * sum;
}

template <int dim>
typename CoSimulation<dim>::Vector CoSimulation<dim>::total_momentum() const
{
  Vector sum = fluid_momentum();
  for (const auto& c : bodies_)
    sum += c.body->linear_momentum();
  return sum;
}

template <int dim>
void CoSimulation<dim>::save(Hdf5File& file, const std::string& group) const
{
  fluid_.save(file, group + "/fluid");
  save_bodies(file, group + "/bodies");
}

template <int dim>
void CoSimulation<dim>::load(const Hdf5File& file, const std::string& group)
{
  fluid_.load(file, group + "/fluid");
  load_bodies(file, group + "/bodies");
}

template <int dim>
void CoSimulation<dim>::save_bodies(Hdf5File& file, const std::string& group) const
{
  file.ensure_group(group);
  for (const auto& c : bodies_)
  {
    const auto state = c.body->state();
    file.write(group + "/" + c.name, state, {state.size()});
    file.write_attribute(group + "/" + c.name, "kind", c.body->kind());
  }
  if (contact_)
  {
    const auto state = contact_->state();
    file.write(group + "_contact", state, {state.size()});
  }
}

template <int dim>
void CoSimulation<dim>::load_bodies(const Hdf5File& file, const std::string& group)
{
  for (auto& c : bodies_)
  {
    const std::string path = group + "/" + c.name;
    if (!file.exists(path))
      throw InputError(file.path(), "checkpoint has no state for body '" + c.name + "'");
    const auto kind = file.read_string_attribute(path, "kind");
    if (kind != c.body->kind())
      throw InputError(file.path(), "body '" + c.name + "' is a " + c.body->kind() +
                                        " here but a " + kind + " in the checkpoint");
    c.body->restore(file.read_doubles(path));
  }
  if (contact_)
  {
    const std::string path = group + "_contact";
    if (!file.exists(path))
      throw InputError(file.path(), "checkpoint has no contact state (written without contact)");
    contact_->restore(file.read_doubles(path));
  }
}

template class CoSimulation<2>;
template class CoSimulation<3>;
} // namespace chipflex::coupling
