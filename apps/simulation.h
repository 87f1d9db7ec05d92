#pragma once
// What `chipflex run` drives: a simulation that advances step by step, reports its
// time, particle frames and probe values, and saves/restores its complete state.
// FluidSimulation (apps/fluid_simulation.h) is the SPH fluid alone; a coupled
// simulation (coupling/) wraps it and adds bodies, their state and their outputs.

#include "apps/particle_output.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace chipflex
{
class Hdf5File;
}

namespace chipflex::apps
{
/// Under a background pressure, the share of the fluid in tension (its running mean over
/// 100 h / c0, sph::FluidSolver::tension_peak_fraction) above which a run warns
/// (Simulation::flow_warnings). Pressure noise puts a few particles in tension in any
/// weakly compressible flow: 0.065 % on Turek & Hron's FSI2 at D/20, 0.15 % on the 2D
/// drill flute; a channel whose background pressure does not cover its suction had 8.6
/// and 11.8 % (docs/sph.md, "Tension").
inline constexpr double tension_warning_fraction = 0.01;

/// With particle shifting, the closest approach of two fluid particles, in particle
/// spacings, below which a run warns that particles clump (Simulation::flow_warnings):
/// at a tenth of the spacing two particles sit nearly on one point, where the kernel's
/// gradient, and so their mutual pressure force, vanishes. Sound runs keep 0.36-0.66 dp
/// (Turek & Hron's FSI2 at D/10); clumped ones reach 1e-3 dp and below (docs/sph.md,
/// "Particle shifting").
inline constexpr double clumping_warning_distance = 0.1;

class Simulation
{
public:
  virtual ~Simulation() = default;
  /// One time step.
  virtual void advance() = 0;
  virtual double time() const = 0;
  virtual std::int64_t step_count() const = 0;
  virtual ParticleFrame frame() const = 0;
  /// CSV column names and the current values, same order.
  virtual std::vector<std::string> probe_columns() const = 0;
  virtual std::vector<double> probe_values() const = 0;
  /// Complete state into / from an open checkpoint file (each part in its own group).
  /// Over MPI every rank calls save() and rank 0 writes: the others pass null.
  virtual void save(Hdf5File* file) const = 0;
  virtual void load(const Hdf5File& file) = 0;
  /// The fluid's artificial speed of sound c0 (derived by the case builder when the case
  /// leaves it at 0), m/s.
  virtual double speed_of_sound() const = 0;
  /// The bodies' lowest natural frequencies that are known, ("body NAME", Hz).
  virtual std::vector<std::pair<std::string, double>> natural_frequencies() const { return {}; }
  /// Fluid particles in the domain now (not the open boundaries' buffers).
  virtual std::size_t n_fluid_particles() const = 0;
  /// Fluid particles removed so far (they left the domain box or turned non-finite).
  virtual std::size_t n_lost_particles() const = 0;
  /// One log line on the k-th removal (time, step, particle id, position, cause).
  virtual std::string describe_lost_particle(std::size_t k) const = 0;
  /// The largest fluid speed of the run so far, m/s.
  virtual double peak_fluid_speed() const = 0;
  virtual double peak_fluid_speed_time() const = 0;
  /// Where and when it was: "t = T s at (x, y[, z])".
  virtual std::string peak_fluid_speed_where() const = 0;
  /// Open boundaries: " inflow_particles=N outflow_particles=M" for the summary line
  /// (particles created by the inlets and removed through the zones), "" without any.
  virtual std::string flow_summary() const { return ""; }
  /// Warnings on the flow over the whole run, one line each ("" when none):
  ///  - under a background pressure, the running mean of the share of the fluid in
  ///    tension passed tension_warning_fraction (the background pressure did not cover
  ///    the suction; particles clump there);
  ///  - with particle shifting, two fluid particles came closer than
  ///    clumping_warning_distance (among the shifted ones or beside a thin skin).
  virtual std::string flow_warnings() const { return ""; }
  /// Open boundaries: the fluid's mass balance since the run's start, one summary.txt
  /// line "mass_balance: ..." (in, out, lost, stored and what is left over, kg; 2D per
  /// metre), given the number of fluid particles at the start; "" without any.
  virtual std::string mass_balance(std::size_t start_fluid_particles) const
  {
    (void)start_fluid_particles;
    return "";
  }
  /// A few lines describing the set-up, printed at the start.
  virtual std::string summary() const = 0;
  /// At the end of a run, finished or stopped: writes the simulation's own result files
  /// under `directory` and returns its result lines for DIR/summary.txt ("" if none).
  virtual std::string finish(const std::string& directory) const
  {
    (void)directory;
    return "";
  }
};
} // namespace chipflex::apps
