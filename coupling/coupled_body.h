#pragma once
// A body as the co-simulation loop sees it: a skin (mbs::SkinBody) the fluid loads,
// and a way to advance over one fluid step with the skin forces held constant. Rigid
// bodies, chains and reduced flexible bodies (mbs/) and SPH solids (sph/) each get one
// small adapter implementing this, so the loop never branches on the body kind.

#include "common/input_error.h"
#include "mbs/skin_body.h"

#include <string>
#include <utility>
#include <vector>

namespace chipflex::coupling
{
template <int dim>
class CoupledBody
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  virtual ~CoupledBody() = default;

  virtual std::string kind() const = 0;
  virtual mbs::SkinBody<dim>& skin() = 0;
  const mbs::SkinBody<dim>& skin() const { return const_cast<CoupledBody*>(this)->skin(); }

  /// Advances the body from t to t + dt under the skin forces last set (and gravity);
  /// the body chooses its own sub-steps or implicit step.
  virtual void advance(double dt) = 0;

  /// Linear momentum of the body plus the impulse its supports (clamp, ground) have
  /// taken up since the start: changed only by external forces. Used by tests.
  virtual Vector linear_momentum() const = 0;

  /// Total mass, kg (2D: per metre of depth); contact uses it for its derived stiffness
  /// and damping (coupling/contact.h).
  virtual double mass() const = 0;

  /// Where within a step t -> t + dt a load held over the step acts, as a fraction of
  /// dt ahead of t, for this body's integrator: contact forces are evaluated at the
  /// positions x + lead dt v so that a contact spring neither gains nor loses energy
  /// over the step (docs/contact.md). 0.5 suits a scheme that integrates a held load
  /// exactly.
  virtual double contact_lead(double /*dt*/) const { return 0.5; }

  /// World position of the body's probe point (the gate's free end: mean of the file's
  /// `tip` node set, the last link's free end, the SPH strip's free-end skin nodes).
  virtual Vector probe_position() const = 0;

  /// Orientation of the body's frame in the world (identity for bodies without one).
  virtual Eigen::Matrix<double, dim, dim> frame_rotation() const
  {
    return Eigen::Matrix<double, dim, dim>::Identity();
  }
  /// Largest elastic displacement of a skin node from its place in the moving frame, m
  /// (0 for rigid bodies).
  virtual double max_deflection() const { return 0; }
  /// Elastic strain energy 1/2 q^T K q of the body's deformation, J (2D: J/m; 0 for
  /// rigid bodies).
  virtual double strain_energy() const { return 0; }
  /// The body's lowest natural frequency, Hz, where the kind knows it (a reduced body's
  /// first normal mode); 0: unknown or rigid. Used to warn of channel acoustics near it.
  virtual double natural_frequency_hz() const { return 0; }
  /// Further named probe values a kind reports (e.g. a moving wall's force and torque),
  /// names with their unit as a suffix ("force_x_N").
  virtual std::vector<std::pair<std::string, double>> extra_probes() const { return {}; }

  /// Puts the body, undeformed, at a new pose with new velocities (world; 2D: the
  /// angular velocity's z) at the run's time t: a chip source's release. Kinds that
  /// cannot be placed throw.
  virtual void place(double /*t*/, const Vector& /*position*/,
                     const Eigen::Matrix<double, dim, dim>& /*rotation*/,
                     const Vector& /*velocity*/, const Eigen::Vector3d& /*angular_velocity*/)
  {
    throw InputError("chip source", "a body of kind " + kind() +
                                        " cannot be released by a chip source (rigid or flexible)");
  }

  /// The complete dynamic state for checkpoints; restore(state()) is exact.
  virtual std::vector<double> state() const = 0;
  virtual void restore(const std::vector<double>& state) = 0;
};
} // namespace chipflex::coupling
