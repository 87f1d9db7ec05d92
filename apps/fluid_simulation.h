#pragma once
// The SPH fluid as a Simulation: built from a case description, gauges from the case.

#include "apps/simulation.h"
#include "sph/case_setup.h"
#include "sph/fluid_solver.h"

#include <memory>

namespace chipflex::apps
{
template <int dim>
class FluidSimulation : public Simulation
{
public:
  explicit FluidSimulation(const sph::CaseDescription<dim>& description);

  /// Bodies (coupling/) may add walls and hooks to fluid() until the first frame or step.
  void advance() override { fluid_->step(); }
  double time() const override { return fluid_->time(); }
  std::int64_t step_count() const override { return fluid_->step_count(); }
  ParticleFrame frame() const override
  {
    fluid_->initialise();
    return particle_frame(*fluid_);
  }
  std::vector<std::string> probe_columns() const override;
  std::vector<double> probe_values() const override;
  void save(Hdf5File& file) const override;
  void load(const Hdf5File& file) override;
  std::string summary() const override;
  std::size_t n_lost_particles() const override { return fluid_->lost_particles().size(); }
  std::string describe_lost_particle(std::size_t k) const override
  {
    return fluid_->lost_particles().at(k).describe();
  }
  double peak_fluid_speed() const override { return fluid_->peak_fluid_speed(); }
  double peak_fluid_speed_time() const override { return fluid_->peak_fluid_speed_time(); }

  sph::FluidSolver<dim>& fluid() { return *fluid_; }
  const sph::CaseDescription<dim>& description() const { return description_; }

private:
  sph::CaseDescription<dim> description_; ///< with derived c0 and domain
  std::unique_ptr<sph::FluidSolver<dim>> fluid_;
};
} // namespace chipflex::apps
