#pragma once
// The co-simulation loop: one SPH fluid and any number of bodies coupled through their
// skins (docs/coupling.md). Per fluid step t -> t + dt:
//
//   1. before the fluid's force pass (HookPoint::before_forces) every body publishes its
//      skin at time t (world positions and velocities) and the fluid moves the body's
//      wall to it;
//   2. the fluid takes its step; its wall pass puts on every wall vertex the reaction of
//      the fluid, split with the barycentric weights that placed each contact;
//   3. after the step (HookPoint::after_step) those vertex forces go to the skin nodes
//      (SkinWall::deliver), with the contact forces of the same step added when contact
//      is on (enable_contact: bodies against the fluid's other walls, permeable barriers
//      included, and against each other; coupling/contact.h), and every body advances
//      over the same dt with them held constant (implicit step or sub-steps, the body's
//      choice).
//
// With the fluid's symplectic scheme the fluid's momentum changes by exactly
// -dt * sum(vertex forces) in a step and each body's by +dt * sum(skin forces), so the
// total momentum of fluid plus bodies is conserved to round-off (tests/coupling).
// The explicit staggering lags the body half a fluid step behind the load; the fluid
// step (CFL on c0 ~ 10 u_max) is far below the body's time scales, so this is
// first-order in a very small dt, and stable because the fluid step also resolves the
// fluid-added-mass time scale of the skin (see docs/coupling.md).

#include "coupling/contact.h"
#include "coupling/coupled_body.h"
#include "coupling/skin_wall.h"
#include "sph/fluid_solver.h"

#include <memory>
#include <string>
#include <vector>

namespace chipflex
{
class Hdf5File;
}

namespace chipflex::coupling
{
template <int dim>
class CoSimulation
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;

  /// Registers the exchange hooks on `fluid`, which must outlive this object.
  explicit CoSimulation(sph::FluidSolver<dim>& fluid);
  CoSimulation(const CoSimulation&) = delete;
  CoSimulation& operator=(const CoSimulation&) = delete;

  /// Couples a body (owned by the caller, outliving this object) before the first
  /// step: its skin becomes a moving wall of the fluid. Lennard-Jones parameters left
  /// at 0 are derived from the fluid as for any wall (sph/lennard_jones_wall.h) with
  /// `expected_pressure` (0: rho0 (c0/10)^2). Returns the body index.
  int add_body(CoupledBody<dim>& body, const std::string& name, sph::WallModel model,
               sph::LennardJonesParameters lennard_jones = {}, double expected_pressure = 0);

  /// Contact between the bodies and with every wall of the fluid that is not a body's
  /// skin (the tank, the case's walls, permeable barriers: walls with fluid_passes, which
  /// the fluid ignores), evaluated each step with the fluid forces. Call after the last
  /// add_body and before the first step.
  void enable_contact(const ContactParameters& parameters);
  /// Null without contact.
  const ContactModel<dim>* contact() const { return contact_.get(); }

  /// A parked body (a chip source's chip waiting for its release, or removed) stands
  /// still where it is, takes no fluid or contact force and touches nothing. Park it
  /// where no fluid reaches its skin (its skin stays a wall of the fluid).
  void set_parked(int b, bool parked);
  bool parked(int b) const { return bodies_[b].parked; }

  /// One fluid step and the bodies with it; returns dt.
  double step();
  double time() const { return fluid_.time(); }

  sph::FluidSolver<dim>& fluid() { return fluid_; }
  const sph::FluidSolver<dim>& fluid() const { return fluid_; }
  int n_bodies() const { return static_cast<int>(bodies_.size()); }
  CoupledBody<dim>& body(int i) { return *bodies_[i].body; }
  const CoupledBody<dim>& body(int i) const { return *bodies_[i].body; }
  const SkinWall<dim>& skin_wall(int i) const { return *bodies_[i].wall; }
  int fluid_wall_id(int i) const { return bodies_[i].wall_id; }

  /// Sum of m v over the fluid particles (dummy boundary particles move with their
  /// walls and carry no momentum of their own).
  Vector fluid_momentum() const;
  /// Fluid plus bodies (CoupledBody::linear_momentum).
  Vector total_momentum() const;

  /// Checkpoint: the fluid (FluidSolver::save) under `group`/fluid and every body's
  /// state under `group`/bodies/<name>. load() restores a run built the same way.
  void save(Hdf5File& file, const std::string& group) const;
  void load(const Hdf5File& file, const std::string& group);
  /// The bodies' part alone (when the fluid is saved by its owner); with contact, its
  /// tangential springs go to `group`_contact.
  void save_bodies(Hdf5File& file, const std::string& group) const;
  void load_bodies(const Hdf5File& file, const std::string& group);

private:
  struct Coupled
  {
    CoupledBody<dim>* body;
    std::unique_ptr<SkinWall<dim>> wall;
    int wall_id;
    std::string name;
    int contact_id = -1; ///< its index in the contact model (-1: none, or an obstacle)
    bool parked = false;
  };
  void publish_skins();
  void exchange_and_advance();

  sph::FluidSolver<dim>& fluid_;
  std::vector<Coupled> bodies_;
  std::unique_ptr<ContactModel<dim>> contact_;
};
} // namespace chipflex::coupling
