#include "mbs/composite_skin.h"

#include "common/input_error.h"

namespace chipflex::mbs
{
template <int dim>
CompositeSkin<dim>::CompositeSkin(std::vector<FloatingFrameBody<dim>*> bodies)
    : bodies_(std::move(bodies))
{
  first_node_.push_back(0);
  for (const auto* b : bodies_)
  {
    const int shift = static_cast<int>(first_node_.back());
    for (auto face : b->skin_faces())
    {
      for (int& n : face)
        n += shift;
      faces_.push_back(face);
    }
    first_node_.push_back(first_node_.back() + b->n_skin_nodes());
  }
}

template <int dim>
void CompositeSkin<dim>::skin_positions(std::vector<Vector>& x) const
{
  x.resize(n_skin_nodes());
  for (std::size_t b = 0; b < bodies_.size(); ++b)
  {
    bodies_[b]->skin_positions(part_);
    std::copy(part_.begin(), part_.end(), x.begin() + first_node_[b]);
  }
}

template <int dim>
void CompositeSkin<dim>::skin_velocities(std::vector<Vector>& v) const
{
  v.resize(n_skin_nodes());
  for (std::size_t b = 0; b < bodies_.size(); ++b)
  {
    bodies_[b]->skin_velocities(part_);
    std::copy(part_.begin(), part_.end(), v.begin() + first_node_[b]);
  }
}

template <int dim>
void CompositeSkin<dim>::set_skin_forces(const std::vector<Vector>& f)
{
  if (f.size() != n_skin_nodes())
    throw InputError("CompositeSkin::set_skin_forces", "one force per skin node expected");
  for (std::size_t b = 0; b < bodies_.size(); ++b)
  {
    part_.assign(f.begin() + first_node_[b], f.begin() + first_node_[b + 1]);
    bodies_[b]->set_skin_forces(part_);
  }
}

template class CompositeSkin<2>;
template class CompositeSkin<3>;
} // namespace chipflex::mbs
