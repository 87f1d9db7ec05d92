// `chipflex bench case CASE.prm [--steps N] [--warm-up N] [--threads N]`: builds the case
// as `chipflex run` does (outputs into a temporary folder, none written while timing),
// takes the warm-up steps (the first steps of a run settle the neighbour lists and the
// time step), then times the next steps and prints the wall time per step, per fluid
// particle and step, and the particle count. Compares models on one case: e.g. a body's
// `wall model`, or the same case on two builds. Under mpirun the fluid is spread over the
// ranks as in `chipflex run` (docs/parallel.md), and rank 0 prints.

#include "apps/bench_case.h"

#include "apps/case_file.h"
#include "apps/simulation_factory.h"
#include "common/command_line.h"
#include "common/input_error.h"
#include "sph/particle_exchange.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <omp.h>

namespace chipflex::apps
{
int bench_case(const Arguments& args)
{
  common::CommandLine cl("chipflex bench case",
                         "Wall time per step of a case file (built as `chipflex run` builds it).");
  cl.add_positional("CASE.prm", "case file");
  cl.add_option("--steps", "N", "steps timed", "2000");
  cl.add_option("--warm-up", "N", "steps taken before timing", "200");
  cl.add_option("--threads", "N", "OpenMP threads (default: OMP_NUM_THREADS or all cores)");
  if (!cl.parse(args))
    return 0;
  if (cl.has("--threads"))
  {
    if (cl.get_int("--threads") < 1)
      throw InputError("--threads", "must be at least 1");
    omp_set_num_threads(int(cl.get_int("--threads")));
  }
  const long steps = cl.get_int("--steps"), warm_up = cl.get_int("--warm-up");
  if (steps < 1 || warm_up < 0)
    throw InputError("--steps", "needs at least one step timed and no negative warm-up");
  std::unique_ptr<sph::MpiSession> mpi;
  if (sph::launched_on_several_ranks())
    mpi = std::make_unique<sph::MpiSession>();
  const bool root = !mpi || mpi->rank() == 0;
  const CaseFile case_file = read_case_file(cl.get("CASE.prm"));
  const auto dir = std::filesystem::temp_directory_path() / "chipflex_bench_case";
  if (root)
    std::filesystem::create_directories(dir);
  auto sim = make_simulation(case_file, dir.string(), mpi != nullptr);
  for (long k = 0; k < warm_up; ++k)
    sim->advance();
  const auto start = std::chrono::steady_clock::now();
  for (long k = 0; k < steps; ++k)
    sim->advance();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::size_t n_fluid = sim->n_fluid_particles(); // a sum over the ranks
  if (!root)
    return 0;
  std::filesystem::remove_all(dir);
  const double per_step = seconds / double(steps);
  std::cout << "case " << cl.get("CASE.prm") << ": " << n_fluid << " fluid particles, " << steps
            << " steps after " << warm_up << " (t = " << sim->time() << " s), "
            << (mpi ? std::to_string(mpi->n_ranks()) + " ranks x " : std::string())
            << omp_get_max_threads() << " thread(s)\n"
            << "  " << 1e3 * per_step << " ms per step, "
            << 1e9 * per_step / double(std::max<std::size_t>(1, n_fluid))
            << " ns per fluid particle and step\n";
  return 0;
}
} // namespace chipflex::apps
