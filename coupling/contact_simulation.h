#pragma once
// Bodies with contact and without fluid: the dry counterpart of CoSimulation, for checks
// of a body or of the contact model on their own (tests/coupling/test_contact.cc). Per
// step t -> t + dt the contact forces are computed from the state at t (ContactModel
// evaluates them half a step ahead), put on the skin nodes, and every body advances
// over dt with them held constant, exactly as in the coupled loop.

#include "coupling/contact.h"
#include "coupling/coupled_body.h"

#include <memory>
#include <vector>

namespace chipflex::coupling
{
template <int dim>
class ContactSimulation
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;

  explicit ContactSimulation(const ContactParameters& parameters) : contact_(parameters) {}
  ContactSimulation(const ContactSimulation&) = delete;
  ContactSimulation& operator=(const ContactSimulation&) = delete;

  /// A fixed or moving wall (kept here; move it with wall()); returns its index.
  int add_wall(const sph::WallSurface<dim>& wall);
  /// A body (owned by the caller, outliving this object); returns its index.
  int add_body(CoupledBody<dim>& body, const std::string& name);

  /// One step of length dt.
  void step(double dt);
  double time() const { return time_; }

  sph::WallSurface<dim>& wall(int w) { return *walls_[w]; }
  CoupledBody<dim>& body(int b) { return *bodies_[b]; }
  const ContactModel<dim>& contact() const { return contact_; }
  /// Sum of the bodies' linear momenta.
  Vector total_momentum() const;

private:
  ContactModel<dim> contact_;
  std::vector<std::unique_ptr<sph::WallSurface<dim>>> walls_;
  std::vector<CoupledBody<dim>*> bodies_;
  double time_ = 0;
};
} // namespace chipflex::coupling
