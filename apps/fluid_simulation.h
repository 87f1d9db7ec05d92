#pragma once
// The SPH fluid as a Simulation: built from a case description, gauges from the case.
// Every frame also writes the fluid's walls (tank, extra walls) to DIR/walls.xdmf, except
// those a body owns (its skin goes to DIR/skins.xdmf).

#include "apps/simulation.h"
#include "apps/surface_output.h"
#include "sph/case_setup.h"
#include "sph/fluid_solver.h"

#include <memory>

namespace chipflex::apps
{
template <int dim>
class FluidSimulation : public Simulation
{
public:
  /// `distributed`: the fluid is spread over the MPI ranks (mpirun; docs/parallel.md).
  /// Every rank then calls every member, as the ranks' sums and gathers need; outputs are
  /// written by rank 0.
  FluidSimulation(const sph::CaseDescription<dim>& description, const std::string& output_directory,
                  bool distributed = false);

  /// Bodies (coupling/) may add walls and hooks to fluid() until the first frame or step.
  void advance() override { fluid_->step(); }
  double time() const override { return fluid_->time(); }
  std::int64_t step_count() const override { return fluid_->step_count(); }
  /// The particles; writes the walls of the same instant beside them.
  ParticleFrame frame() const override;
  std::vector<std::string> probe_columns() const override;
  std::vector<double> probe_values() const override;
  void save(Hdf5File* file) const override;
  void load(const Hdf5File& file) override;
  std::string summary() const override;
  std::size_t n_fluid_particles() const override;
  double speed_of_sound() const override { return fluid_->parameters().speed_of_sound; }
  std::size_t n_lost_particles() const override { return fluid_->lost_particles().size(); }
  std::string describe_lost_particle(std::size_t k) const override
  {
    return fluid_->lost_particles().at(k).describe();
  }
  double peak_fluid_speed() const override { return fluid_->peak_fluid_speed(); }
  double peak_fluid_speed_time() const override { return fluid_->peak_fluid_speed_time(); }
  std::string peak_fluid_speed_where() const override;
  std::string flow_summary() const override;
  std::string flow_warnings() const override;
  std::string mass_balance(std::size_t start_fluid_particles) const override;

  sph::FluidSolver<dim>& fluid() { return *fluid_; }
  /// The wall `id` of fluid() is a body's skin: leave it out of DIR/walls.xdmf.
  void exclude_from_wall_output(int id) { excluded_walls_.push_back(id); }
  const sph::CaseDescription<dim>& description() const { return description_; }
  /// This process writes the output files (false on the MPI ranks other than 0).
  bool writes_outputs() const { return writes_; }

private:
  sph::CaseDescription<dim> description_; ///< with derived c0 and domain
  std::unique_ptr<sph::FluidSolver<dim>> fluid_;
  mutable SurfaceOutput<dim> walls_;
  bool writes_ = true; ///< false on the ranks other than 0
  std::vector<int> excluded_walls_;
};
} // namespace chipflex::apps
