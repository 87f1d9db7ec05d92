#pragma once
// The SPH fluid plus coupled bodies as a `chipflex run` Simulation (2D). The fluid is
// the FluidSimulation of the same case; coupling::CoSimulation exchanges skin motion
// and skin forces every fluid step. Outputs beside the fluid's: the deformed skins
// (DIR/skins.xdmf, with every particle frame: displacement from the initial skin,
// velocity, fluid force), each body's probe displacement (probes.csv columns and
// DIR/<body>_displacement.csv: time_s, dx_m, dy_m), and a summary line with the RMS error
// against the case's reference curve and the wall time.

#include "apps/body_case_keys.h"
#include "apps/fluid_simulation.h"
#include "apps/surface_output.h"
#include "coupling/co_simulation.h"
#include "coupling/displacement_history.h"

#include <chrono>
#include <memory>

namespace chipflex::apps
{
class CoupledSimulation : public Simulation
{
public:
  CoupledSimulation(const sph::CaseDescription<2>& fluid_case, const BodyCase& bodies,
                    const std::string& output_directory);

  void advance() override;
  double time() const override { return fluid_.time(); }
  std::int64_t step_count() const override { return fluid_.step_count(); }
  /// The fluid's frame; writes the skins of the same instant beside it.
  ParticleFrame frame() const override;
  std::vector<std::string> probe_columns() const override;
  std::vector<double> probe_values() const override;
  void save(Hdf5File& file) const override;
  void load(const Hdf5File& file) override;
  std::string summary() const override;
  std::size_t n_lost_particles() const override { return fluid_.n_lost_particles(); }
  std::string describe_lost_particle(std::size_t k) const override
  {
    return fluid_.describe_lost_particle(k);
  }
  double peak_fluid_speed() const override { return fluid_.peak_fluid_speed(); }
  std::string flow_summary() const override { return fluid_.flow_summary(); }
  double peak_fluid_speed_time() const override { return fluid_.peak_fluid_speed_time(); }

  /// Writes the displacement CSVs; returns one summary line per body (RMS errors, wall time).
  std::string finish(const std::string& output_directory) const override;

private:
  void record();

  FluidSimulation<2> fluid_;
  BodyCase case_;
  std::vector<std::unique_ptr<coupling::CoupledBody<2>>> bodies_;
  std::unique_ptr<coupling::CoSimulation<2>> cosim_;
  std::vector<Eigen::Vector2d> probe_start_;
  std::vector<coupling::DisplacementHistory> histories_;
  std::vector<std::vector<Eigen::Vector2d>> reference_skins_; ///< skin nodes at t = 0
  mutable SurfaceOutput<2> skins_;
  std::chrono::steady_clock::time_point started_;
  double restored_wall_seconds_ = 0;
};
} // namespace chipflex::apps
