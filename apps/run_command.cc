// `chipflex run CASE.prm --out DIR`: builds the simulation from the case file and
// advances it to the end time, writing particle frames (DIR/particles.xdmf, with the
// walls and skins of the same instants), gauges (DIR/probes.csv), DIR/summary.txt and, on
// request, atomic checkpoints (DIR/checkpoint.h5). A run the solver stops
// (SimulationError: a blow-up, a particle leaving the domain) still writes a frame at the
// stop time, its gauges, its result files and a summary.txt saying status=stopped, then
// exits non-zero (main: status 3). docs/output.md lists the outputs.
//
// Coupling plugs in at make_simulation(): it returns any Simulation (a fluid alone
// today; fluid plus bodies when the case has `subsection bodies`). The loop below only
// knows the Simulation interface; the run cadence (next frame, probe and checkpoint
// times) is saved in the checkpoint's /run group beside the simulation's own groups.

#include "apps/case_file.h"
#include "apps/channel_acoustics.h"
#include "apps/commands.h"
#include "apps/fluid_continuity.h"
#include "apps/jam_watch.h"
#include "apps/probe_output.h"
#include "apps/progress_meter.h"
#include "apps/simulation_factory.h"
#include "common/atomic_output.h"
#include "common/command_line.h"
#include "common/hdf5_file.h"
#include "common/input_error.h"
#include "sph/particle_exchange.h"

#include <algorithm>
#include <deal.II/base/parameter_handler.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <omp.h>
#include <sstream>
#include <stdexcept>

namespace chipflex::apps
{
namespace
{
struct Cadence
{
  double next_frame = 0, next_probe = 0, next_checkpoint = 0;
};

void write_checkpoint(const std::string& path, const Simulation& sim, const Cadence& cadence,
                      const FluidContinuityCheck& continuity, const JamWatch* jam, bool root)
{
  if (!root) // over MPI: this rank's part of the gather; rank 0 writes
  {
    sim.save(nullptr);
    return;
  }
  AtomicOutput out(path);
  {
    Hdf5File h5(out.temporary_path(), Hdf5File::Mode::create);
    h5.ensure_group("/run");
    h5.write_attribute("/run", "time", sim.time());
    h5.write_attribute("/run", "step", std::int64_t(sim.step_count()));
    h5.write_attribute("/run", "next_frame", cadence.next_frame);
    h5.write_attribute("/run", "next_probe", cadence.next_probe);
    h5.write_attribute("/run", "next_checkpoint", cadence.next_checkpoint);
    continuity.save(h5, "/run");
    if (jam)
      jam->save(h5, "/run");
    sim.save(&h5);
  }
  out.commit();
}

/// DIR/summary.txt: a status line (status=finished|stopped, reason="..." when stopped,
/// time, steps, frames), then the simulation's result lines. Returns the text.
std::string write_summary(const std::string& dir, const Simulation& sim, std::size_t frames,
                          const std::string& stop_reason, const FluidContinuityCheck& continuity,
                          bool open_boundaries, const JamWatch* jam, bool root)
{
  std::ostringstream s;
  s.precision(9);
  s << "status=" << (stop_reason.empty() ? "finished" : "stopped");
  if (!stop_reason.empty())
  {
    // One line, and the value stays one quoted field for scripts.
    std::string reason = stop_reason;
    for (char& c : reason)
      if (c == '"' || c == '\n' || c == '\r')
        c = c == '"' ? '\'' : ' ';
    s << " reason=\"" << reason << "\"";
  }
  s << " t_s=" << sim.time() << " steps=" << sim.step_count() << " frames=" << frames
    << " lost_particles=" << sim.n_lost_particles()
    << " peak_fluid_speed_m_s=" << sim.peak_fluid_speed() << sim.flow_summary() << "\n";
  if (open_boundaries)
    s << continuity.summary_line() << "\n" << sim.mass_balance(continuity.start()) << "\n";
  if (jam)
    s << jam->summary_line() << "\n";
  if (const std::string warnings = sim.flow_warnings(); !warnings.empty())
    s << warnings << "\n";
  const std::string results = sim.finish(dir);
  if (!results.empty())
    s << results << "\n";
  if (!root)
    return s.str();
  AtomicOutput out(dir + "/summary.txt");
  {
    std::ofstream f(out.temporary_path());
    f << s.str();
    if (!f)
      throw std::runtime_error("cannot write " + out.temporary_path());
  }
  out.commit();
  return s.str();
}

/// Next multiple of `interval` strictly after `time` (k * interval, no drift).
double next_after(double time, double interval)
{
  if (!(interval > 0))
    return 1e300;
  double k = std::floor(time / interval + 1e-9) + 1;
  return k * interval;
}
} // namespace

int run_command(const Arguments& args)
{
  common::CommandLine cl("chipflex run CASE.prm --out DIR [options]",
                         "Run an SPH case: particle frames (DIR/particles.xdmf), walls "
                         "(DIR/walls.xdmf), body skins (DIR/skins.xdmf), gauges (DIR/probes.csv), "
                         "DIR/summary.txt, checkpoints (DIR/checkpoint.h5); docs/output.md. Under "
                         "mpirun -np N the fluid is spread over N ranks, with OpenMP threads in "
                         "each (docs/parallel.md).");
  cl.add_positional("CASE.prm", "case file (deal.II ParameterHandler format)", false);
  cl.add_option("--out", "DIR", "output folder (created)");
  cl.add_option("--threads", "N", "OpenMP threads (default: OMP_NUM_THREADS or all cores)");
  cl.add_option("--checkpoint-every", "T",
                "write DIR/checkpoint.h5 every T s of simulated time (and at the end)");
  cl.add_option("--restart", "FILE", "continue from a checkpoint written by this case");
  cl.add_option("--end-time", "T", "override the case's end time, s");
  cl.add_flag("--print-keys", "print every case key with its documentation and default");
  if (!cl.parse(args))
    return 0;
  if (cl.flag("--print-keys"))
  {
    std::cout << documented_case_keys();
    return 0;
  }
  if (!cl.has("CASE.prm"))
    throw InputError("chipflex run", "missing CASE.prm (chipflex run --help)");
  // Under mpirun the fluid is spread over the ranks (docs/parallel.md). Every rank runs
  // this loop and calls the simulation alike (its sums and gathers are collective); rank
  // 0 prints and writes.
  std::unique_ptr<sph::MpiSession> mpi;
  if (sph::launched_on_several_ranks())
    mpi = std::make_unique<sph::MpiSession>();
  const bool root = !mpi || mpi->rank() == 0;
  if (!root)
    std::cout.setstate(std::ios::badbit);
  if (!cl.has("--out"))
    throw InputError("chipflex run", "missing --out DIR");
  if (cl.has("--threads"))
  {
    if (cl.get_int("--threads") < 1)
      throw InputError("--threads", "must be at least 1");
    omp_set_num_threads(int(cl.get_int("--threads")));
  }
  const double checkpoint_every =
      cl.has("--checkpoint-every") ? cl.get_double("--checkpoint-every") : 0;
  if (cl.has("--checkpoint-every") && !(checkpoint_every > 0))
    throw InputError("--checkpoint-every", "must be a positive time in seconds");

  const CaseFile case_file = read_case_file(cl.get("CASE.prm"));
  double end_time = case_file.end_time;
  if (cl.has("--end-time"))
    end_time = cl.get_double("--end-time");
  const double frame_interval = case_file.frame_interval;
  const double probe_interval = case_file.probe_interval;
  const std::string dir = cl.get("--out");
  if (root)
    std::filesystem::create_directories(dir);
  const std::string checkpoint_path = dir + "/checkpoint.h5";

  auto sim = make_simulation(case_file, dir, mpi != nullptr);
  std::cout << sim->summary() << std::endl;
  {
    auto frequencies = sim->natural_frequencies();
    for (double f : case_file.watched_frequencies)
      frequencies.emplace_back("the watched frequency", f);
    const double length = case_file.dimension == 2 ? channel_length(case_file.case_2d)
                                                   : channel_length(case_file.case_3d);
    for (const auto& line : acoustic_warnings(sim->speed_of_sound(), length, frequencies))
      std::cout << line << std::endl;
    // A running mean shorter than the channel's acoustic period follows its ringing (tens
    // of kPa in a flute) and can report a jam that is none.
    const double period = 4 * length / sim->speed_of_sound();
    if (case_file.jam_watch.enabled() && length > 0 && case_file.jam_watch.averaging_time < period)
      std::cout << "warning: jam watch: the averaging time " << case_file.jam_watch.averaging_time
                << " s is shorter than the channel's acoustic period 4 L / c0 = " << period
                << " s; its ringing can pass for a jam (docs/output.md, \"The jam watch\")"
                << std::endl;
    // While an inlet ramps up, the flow is below its reference and the acceleration raises
    // the pressure: both criteria can fire without a jam (a chip-free flute did).
    auto longest_ramp = [](const auto& zones)
    {
      double r = 0;
      for (const auto& z : zones)
        if (z.kind == sph::OpenBoundaryKind::inlet)
          r = std::max(r, z.ramp_time);
      return r;
    };
    const double ramp = case_file.dimension == 2 ? longest_ramp(case_file.case_2d.open_boundaries)
                                                 : longest_ramp(case_file.case_3d.open_boundaries);
    if (case_file.jam_watch.enabled() && case_file.jam_watch.start_time < ramp)
      std::cout << "warning: jam watch: the start time " << case_file.jam_watch.start_time
                << " s is before the inlet's ramp ends at " << ramp
                << " s; the ramp's low flow and its acceleration's pressure can pass for a jam"
                << std::endl;
  }
  ParticleOutput particles(dir, root);
  const std::vector<std::string> columns = sim->probe_columns();
  ProbeOutput probes(dir + "/probes.csv", columns, root);
  // The run's watches: the fluid's continuity and, when the case asks, the jam.
  FluidContinuityCheck continuity(case_file.tear_warning_fraction,
                                  case_file.dimension == 2
                                      ? case_file.case_2d.fluid.background_pressure
                                      : case_file.case_3d.fluid.background_pressure);
  const bool open_boundaries = case_file.dimension == 2
                                   ? !case_file.case_2d.open_boundaries.empty()
                                   : !case_file.case_3d.open_boundaries.empty();
  std::unique_ptr<JamWatch> jam;
  if (case_file.jam_watch.enabled())
    jam = std::make_unique<JamWatch>(case_file.jam_watch, columns);
  Cadence cadence;
  if (cl.has("--restart"))
  {
    const Hdf5File h5(cl.get("--restart"), Hdf5File::Mode::read);
    sim->load(h5);
    cadence.next_frame = h5.read_double_attribute("/run", "next_frame");
    cadence.next_probe = h5.read_double_attribute("/run", "next_probe");
    cadence.next_checkpoint = next_after(sim->time(), checkpoint_every);
    continuity.load(h5, "/run");
    if (jam)
      jam->load(h5, "/run");
    particles.resume(sim->time());
    probes.resume(sim->time());
    std::cout << "restarted from " << cl.get("--restart") << " at t = " << sim->time()
              << " s, step " << sim->step_count() << std::endl;
  }
  else
  {
    particles.write(sim->time(), sim->frame());
    if (!probes.empty())
      probes.add(sim->time(), sim->probe_values());
    probes.flush();
    cadence.next_frame = next_after(sim->time(), frame_interval);
    cadence.next_probe = next_after(sim->time(), probe_interval);
    cadence.next_checkpoint = next_after(sim->time(), checkpoint_every);
  }
  continuity.update(sim->time(), sim->n_fluid_particles());
  ProgressMeter progress(sim->time(), end_time);
  std::size_t lost_reported = sim->n_lost_particles();
  const auto report_lost = [&]
  {
    for (; lost_reported < sim->n_lost_particles(); ++lost_reported)
      std::cout << "removed: " << sim->describe_lost_particle(lost_reported) << " ("
                << lost_reported + 1 << " lost so far)" << std::endl;
  };
  try
  {
    while (sim->time() < end_time)
    {
      sim->advance();
      report_lost();
      const std::string tearing = continuity.update(sim->time(), sim->n_fluid_particles());
      if (!tearing.empty())
        std::cout << tearing << std::endl;
      const double t = sim->time();
      if (t >= cadence.next_probe)
      {
        if (!probes.empty())
        {
          const auto row = sim->probe_values();
          probes.add(t, row);
          if (jam)
            if (const std::string line = jam->update(t, row); !line.empty())
              std::cout << line << std::endl;
        }
        cadence.next_probe = next_after(t, probe_interval);
      }
      if (t >= cadence.next_frame || t >= end_time)
      {
        particles.write(t, sim->frame());
        probes.flush();
        cadence.next_frame = next_after(t, frame_interval);
      }
      if (t >= cadence.next_checkpoint || (checkpoint_every > 0 && t >= end_time))
      {
        cadence.next_checkpoint = next_after(t, checkpoint_every);
        // probes.csv first: a run killed after this checkpoint resumes from rows that
        // reach its time (ProbeOutput::resume keeps the rows up to the restart time).
        probes.flush();
        write_checkpoint(checkpoint_path, *sim, cadence, continuity, jam.get(), root);
      }
      if (root) // it writes to stderr
        progress.update(t, sim->step_count());
      if (jam && jam->run_done(t))
      {
        std::cout << "jam watch: the run ends " << case_file.jam_watch.stop_after
                  << " s after the jam (probes/jam watch/stop after)" << std::endl;
        if (t > particles.last_time())
          particles.write(t, sim->frame());
        break;
      }
    }
  }
  catch (const SimulationError& e)
  {
    report_lost();
    // The state the solver stopped in is what the user needs to see: a frame at the stop
    // time (unless the last frame is already there), the gauges up to it, the result
    // files and the summary. The last checkpoint stays as it was.
    if (root)
      progress.finish(sim->time(), sim->step_count());
    try
    {
      if (sim->time() > particles.last_time())
        particles.write(sim->time(), sim->frame());
      probes.flush();
      std::cout << write_summary(dir, *sim, particles.n_frames(), e.what(), continuity,
                                 open_boundaries, jam.get(), root)
                << std::flush;
    }
    catch (const std::exception& w)
    {
      // The stop is the news; a failing output must not hide it.
      std::cerr << "chipflex run: outputs at the stop incomplete: " << w.what() << "\n";
    }
    throw;
  }
  if (root)
    progress.finish(sim->time(), sim->step_count());
  probes.flush();
  std::cout << write_summary(dir, *sim, particles.n_frames(), "", continuity, open_boundaries,
                             jam.get(), root)
            << std::flush;
  std::cout << "finished at t = " << sim->time() << " s after " << sim->step_count() << " steps; "
            << particles.n_frames() << " frames in " << dir
            << "/particles.xdmf; lost_particles=" << sim->n_lost_particles()
            << " peak_fluid_speed_m_s=" << sim->peak_fluid_speed() << " ("
            << sim->peak_fluid_speed_where() << ")" << sim->flow_summary() << std::endl;
  return 0;
}
} // namespace chipflex::apps
