#pragma once
// Bodies of mbs/ (a rigid body, a rigid chain, a reduced floating-frame body — all
// FloatingFrameBody in one MultibodySystem) as a coupled body. The system's
// generalised-alpha step is implicit and not limited by the stiffest retained mode, so
// by default the body takes one step per fluid step; `max_step` splits a longer fluid
// step into equal sub-steps with the skin forces held.

#include "coupling/coupled_body.h"
#include "mbs/multibody_system.h"

#include <functional>
#include <memory>
#include <string>

namespace chipflex::coupling
{
template <int dim>
class MultibodyCoupledBody : public CoupledBody<dim>
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;

  /// @param skin the skin of one of the system's bodies, or a CompositeSkin over several;
  ///        kept alive by this object when given as `owned_skin`
  using Probe = std::function<Vector(const mbs::MultibodySystem<dim>&)>;

  MultibodyCoupledBody(std::string kind, std::unique_ptr<mbs::MultibodySystem<dim>> system,
                       mbs::SkinBody<dim>& skin, double max_step = 0, Probe probe = {});
  MultibodyCoupledBody(std::string kind, std::unique_ptr<mbs::MultibodySystem<dim>> system,
                       std::unique_ptr<mbs::SkinBody<dim>> owned_skin, double max_step = 0,
                       Probe probe = {});

  std::string kind() const override { return kind_; }
  mbs::SkinBody<dim>& skin() override { return *skin_; }
  void advance(double dt) override;
  /// Sum over the system's bodies (supports such as a clamp to ground are not counted).
  Vector linear_momentum() const override;
  double mass() const override;
  /// Symplectic Euler in n sub-steps: (n - 1) / 2n; generalised-alpha: 1/2 + (1 - gamma) / n
  /// (the step's velocity update weights the previous load by 1 - gamma); midpoint: 1/2.
  double contact_lead(double dt) const override;
  /// The probe given at construction; without one, body 0's frame origin.
  Vector probe_position() const override;
  /// Body 0's frame rotation and the largest elastic skin displacement of body 0.
  Eigen::Matrix<double, dim, dim> frame_rotation() const override;
  double max_deflection() const override;
  /// Sum of the bodies' modal strain energies (mbs::FloatingFrameBody::strain_energy).
  double strain_energy() const override;
  /// One free body only (a rigid or flexible kind): pose, velocities, q = q' = 0.
  void place(double t, const Vector& position, const Eigen::Matrix<double, dim, dim>& rotation,
             const Vector& velocity, const Eigen::Vector3d& angular_velocity) override;
  std::vector<double> state() const override { return system_->save_state(); }
  void restore(const std::vector<double>& state) override { system_->restore_state(state); }

  double natural_frequency_hz() const override { return natural_frequency_hz_; }
  /// Set by the kind that knows it (the flexible kind, from its body file).
  void set_natural_frequency_hz(double hz) { natural_frequency_hz_ = hz; }

  mbs::MultibodySystem<dim>& system() { return *system_; }
  const mbs::MultibodySystem<dim>& system() const { return *system_; }
  long steps() const { return steps_; }

private:
  std::string kind_;
  std::unique_ptr<mbs::MultibodySystem<dim>> system_;
  std::unique_ptr<mbs::SkinBody<dim>> owned_skin_;
  mbs::SkinBody<dim>* skin_;
  double natural_frequency_hz_ = 0;
  double max_step_;
  Probe probe_;
  long steps_ = 0;
};
} // namespace chipflex::coupling
