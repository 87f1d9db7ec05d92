#include "coupling/skin_wall.h"

#include <stdexcept>

namespace chipflex::coupling
{
template <int dim>
SkinWall<dim>::SkinWall(mbs::SkinBody<dim>& body, const std::string& name, sph::WallModel model,
                        const sph::LennardJonesParameters& lennard_jones, bool fluid_passes)
    : body_(body)
{
  surface_.name = name;
  surface_.model = model;
  surface_.lennard_jones = lennard_jones;
  surface_.fluid_passes = fluid_passes;
  surface_.slides_in_place = body.skin_slides_in_place();
  surface_.moves = true;
  surface_.faces = body.skin_faces();
  const int n = static_cast<int>(body.n_skin_nodes());
  for (const auto& face : surface_.faces)
    for (int v : face)
      if (v < 0 || v >= n)
        throw std::logic_error("SkinWall '" + name + "': face refers to skin node " +
                               std::to_string(v) + " of " + std::to_string(n));
  delivered_.assign(n, Vector::Zero());
  contact_.assign(n, Vector::Zero());
  publish();
}

template <int dim>
void SkinWall<dim>::publish()
{
  body_.skin_positions(surface_.vertices);
  body_.skin_velocities(surface_.velocities);
}

template <int dim>
void SkinWall<dim>::deliver(const std::vector<Vector>& vertex_forces,
                            const std::vector<Vector>* contact_forces)
{
  if (vertex_forces.size() != body_.n_skin_nodes())
    throw std::logic_error("SkinWall '" + surface_.name +
                           "': " + std::to_string(vertex_forces.size()) + " forces for " +
                           std::to_string(body_.n_skin_nodes()) + " skin nodes");
  delivered_ = vertex_forces;
  if (!contact_forces)
  {
    body_.set_skin_forces(vertex_forces);
    return;
  }
  if (contact_forces->size() != vertex_forces.size())
    throw std::logic_error("SkinWall '" + surface_.name + "': contact forces of another skin");
  contact_ = *contact_forces;
  sum_.resize(vertex_forces.size());
  for (std::size_t i = 0; i < sum_.size(); ++i)
    sum_[i] = vertex_forces[i] + contact_[i];
  body_.set_skin_forces(sum_);
}

template class SkinWall<2>;
template class SkinWall<3>;
} // namespace chipflex::coupling
