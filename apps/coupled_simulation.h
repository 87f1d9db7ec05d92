#pragma once
// The SPH fluid plus coupled bodies as a `chipflex run` Simulation, 2D or 3D. The fluid
// is the FluidSimulation of the same case; coupling::CoSimulation exchanges skin motion
// and skin forces every fluid step. Outputs beside the fluid's: the deformed skins
// (DIR/skins.xdmf, with every particle frame: displacement from the initial skin,
// velocity, fluid force), per body its probe point's position and displacement, frame
// rotation, largest elastic deflection and what its kind adds (probes.csv columns
// <body>_*), DIR/<body>_displacement.csv (time_s, dx_m, dy_m[, dz_m]), and a summary
// line per body (with the RMS error against the case's reference curve, if any).

#include "apps/body_case_keys.h"
#include "apps/contact_case_keys.h"
#include "apps/fluid_simulation.h"
#include "apps/surface_output.h"
#include "coupling/chip_source.h"
#include "coupling/co_simulation.h"

#include <array>
#include <chrono>
#include <memory>

namespace chipflex::apps
{
template <int dim>
class CoupledSimulation : public Simulation
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;

  /// `distributed`: the fluid over the MPI ranks, the bodies whole on every rank (each
  /// rank moves its copy alike under the fluid forces summed over the ranks); rank 0
  /// writes.
  CoupledSimulation(const sph::CaseDescription<dim>& fluid_case, BodyCase<dim> bodies,
                    const std::string& output_directory, const ContactCase& contact = {},
                    bool distributed = false);

  void advance() override;
  double time() const override { return fluid_.time(); }
  std::int64_t step_count() const override { return fluid_.step_count(); }
  /// The fluid's frame; writes the skins of the same instant beside it.
  ParticleFrame frame() const override;
  std::vector<std::string> probe_columns() const override;
  std::vector<double> probe_values() const override;
  void save(Hdf5File* file) const override;
  void load(const Hdf5File& file) override;
  std::string summary() const override;
  std::size_t n_fluid_particles() const override { return fluid_.n_fluid_particles(); }
  double speed_of_sound() const override { return fluid_.speed_of_sound(); }
  std::vector<std::pair<std::string, double>> natural_frequencies() const override;
  std::size_t n_lost_particles() const override { return fluid_.n_lost_particles(); }
  std::string describe_lost_particle(std::size_t k) const override
  {
    return fluid_.describe_lost_particle(k);
  }
  double peak_fluid_speed() const override { return fluid_.peak_fluid_speed(); }
  std::string flow_summary() const override { return fluid_.flow_summary(); }
  std::string flow_warnings() const override { return fluid_.flow_warnings(); }
  std::string mass_balance(std::size_t start) const override { return fluid_.mass_balance(start); }
  double peak_fluid_speed_time() const override { return fluid_.peak_fluid_speed_time(); }
  std::string peak_fluid_speed_where() const override { return fluid_.peak_fluid_speed_where(); }

  /// Writes the displacement CSVs; returns one summary line per body (RMS errors, wall time).
  std::string finish(const std::string& output_directory) const override;

private:
  using Sample = std::array<double, 1 + dim>; ///< time, displacement
  void record();

  FluidSimulation<dim> fluid_;
  BodyCase<dim> case_;
  std::unique_ptr<coupling::CoSimulation<dim>> cosim_;
  std::unique_ptr<coupling::ChipSource<dim>> chip_source_; ///< null without one
  std::vector<Vector> probe_start_;
  std::vector<std::vector<Sample>> histories_;
  std::vector<Sample> last_step_; ///< per body: the probe at the last step, for interpolation
  std::vector<std::vector<Vector>> reference_skins_; ///< skin nodes at t = 0
  mutable SurfaceOutput<dim> skins_;
  /// The axis of the walls' contact torque probes (contact/torque axis).
  Vector torque_point_ = Vector::Zero();
  Eigen::Vector3d torque_direction_ = Eigen::Vector3d::UnitZ();
  std::chrono::steady_clock::time_point started_;
  double restored_wall_seconds_ = 0;
};
} // namespace chipflex::apps
