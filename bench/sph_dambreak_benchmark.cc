// DualSPHysics' CaseDambreakVal2D (examples/main/01_DamBreak validation case): a 1 m wide,
// 2 m high water column in a 4 m x 3 m tank, dp = 0.01 m, h = 0.014142 m,
// c0 = 88.589 m/s, Wendland kernel, artificial viscosity 0.02, Fourtakas density
// diffusion 0.1, Verlet (Euler every 40 steps), CFL 0.2, one layer of dynamic boundary
// particles: 20,000 fluid + 1,002 boundary particles. Runs to t = 0.05 s and reports
// particle-steps per second of the stepping loop (set-up excluded).

#include "bench/benchmarks.h"
#include "common/command_line.h"
#include "sph/case_setup.h"
#include "sph/particle_exchange.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <omp.h>
#include <optional>

namespace chipflex::bench
{
namespace
{
/// Steps `fluid` to `end_time` (the first step, with the set-up and first sort, outside
/// the timing) and prints the figures, last line particle_steps_per_s=<value>. Under
/// mpirun the fluid is spread over the ranks (sph/particle_exchange.h); rank 0 prints the
/// global figures and the slowest rank's time split into compute, halo exchange,
/// migration and the time step's reduction.
template <int dim>
void time_fluid(sph::FluidSolver<dim>& fluid, double end_time, const std::string& name)
{
  std::shared_ptr<sph::ParticleExchange<dim>> exchange;
  if (sph::launched_on_several_ranks())
  {
    exchange = std::make_shared<sph::ParticleExchange<dim>>();
    fluid.distribute(exchange);
  }
  fluid.step();
  const sph::ExchangeStatistics before =
      exchange ? exchange->statistics() : sph::ExchangeStatistics{};
  const auto t0 = std::chrono::steady_clock::now();
  const std::int64_t first_step = fluid.step_count();
  while (fluid.time() < end_time)
    fluid.step();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::int64_t steps = fluid.step_count() - first_step;
  // Per rank: seconds, halo, migration, reduction (maxima); owned fluid, ghosts (sums).
  double maxima[4] = {seconds, 0, 0, 0};
  double sums[2] = {double(fluid.n_fluid() - fluid.n_ghosts()), double(fluid.n_ghosts())};
  int rank = 0, n_ranks = 1;
  if (exchange)
  {
    const auto& after = exchange->statistics();
    maxima[1] = after.halo_seconds - before.halo_seconds;
    maxima[2] = after.migration_seconds - before.migration_seconds;
    maxima[3] = after.reduction_seconds - before.reduction_seconds;
    exchange->maximum(maxima, 4);
    exchange->sum(sums, 2);
    rank = exchange->rank();
    n_ranks = exchange->n_ranks();
  }
  if (rank != 0)
    return;
  const double n = double(fluid.n_boundary()) + sums[0];
  std::printf("case=%s (t = %g s)\n", name.c_str(), fluid.time());
  std::printf("particles=%.0f (fluid %.0f, boundary %zu)\n", n, sums[0], fluid.n_boundary());
  std::printf("steps=%lld\n", static_cast<long long>(steps));
  std::printf("ranks=%d\n", n_ranks);
  std::printf("threads=%d\n", omp_get_max_threads());
  std::printf("seconds=%.3f\n", maxima[0]);
  if (exchange)
  {
    std::printf("ghosts_per_rank=%.0f\n", sums[1] / n_ranks);
    std::printf("slowest_rank_seconds: halo=%.3f migration=%.3f reduction=%.3f\n", maxima[1],
                maxima[2], maxima[3]);
  }
  std::printf("bytes_per_particle=%.1f\n",
              double(fluid.memory_bytes()) / double(fluid.n_particles()));
  std::printf("particle_steps_per_s=%.4g\n", n * double(steps) / maxima[0]);
}
} // namespace

int sph_dambreak2d_benchmark(const Arguments& args)
{
  std::optional<sph::MpiSession> mpi; // under mpirun: the fluid over the ranks
  if (sph::launched_on_several_ranks())
    mpi.emplace();
  common::CommandLine cl(
      "chipflex bench sph-dambreak2d [options]",
      "DualSPHysics CaseDambreakVal2D to t = 0.05 s; last line "
      "particle_steps_per_s=<value> (DualSPHysics 5.4 CPU: 3.11e6 on 2 threads)");
  cl.add_option("--threads", "N", "OpenMP threads (default: OMP_NUM_THREADS or all cores)");
  cl.add_option("--end-time", "T", "simulated time, s", "0.05");
  cl.add_option("--spacing", "DP", "particle spacing, m", "0.01");
  if (!cl.parse(args))
    return 0;
  if (cl.has("--threads"))
    omp_set_num_threads(int(cl.get_int("--threads")));

  using Vector = Eigen::Vector2d;
  sph::CaseDescription<2> c;
  auto& p = c.fluid;
  p.particle_spacing = cl.get_double("--spacing");
  p.smoothing_coefficient = 1.0; // h = sqrt(2) dp = 0.014142 m
  p.reference_density = 1000;
  p.speed_of_sound = 88.589;
  p.gravity = Vector(0, -9.81);
  p.viscosity = sph::ViscosityModel::artificial;
  p.artificial_viscosity = 0.02;
  p.density_diffusion = sph::DensityDiffusionModel::fourtakas;
  p.density_diffusion_delta = 0.1;
  p.scheme = sph::TimeScheme::verlet;
  p.verlet_euler_every = 40;
  p.cfl = 0.2;
  c.fluid_blocks.push_back({Vector(0, 0), Vector(1, 2)});
  c.tank.min = Vector(0, 0);
  c.tank.max = Vector(4, 3);
  c.tank.model = sph::WallModel::dummy_particles;
  c.tank.layers = 1;
  auto fluid = sph::build_fluid(c);

  time_fluid(*fluid, cl.get_double("--end-time"),
             "DualSPHysics CaseDambreakVal2D, dp " + std::to_string(p.particle_spacing) + " m");
  return 0;
}

// DualSPHysics' 3D CaseDambreak (examples/main/01_DamBreak/CaseDambreak_Def.xml): a
// 0.4 x 0.67 x 0.3 m water column in a 1.6 x 0.67 x 0.4 m open tank with a 0.12 x 0.12 x
// 0.45 m square column at (0.9, 0.24, 0), dp = 0.0085 m, h = sqrt(3) dp, coefsound 20,
// CFL 0.2, Verlet (Euler every 40 steps), artificial viscosity 0.1, no density
// diffusion, one layer of dynamic boundary particles. DualSPHysics uses the cubic spline
// kernel there; chipflex has Wendland's, which costs the same per pair.
int sph_dambreak3d_benchmark(const Arguments& args)
{
  std::optional<sph::MpiSession> mpi; // under mpirun: the fluid over the ranks
  if (sph::launched_on_several_ranks())
    mpi.emplace();
  common::CommandLine cl("chipflex bench sph-dambreak3d [options]",
                         "DualSPHysics CaseDambreak (3D) to t = 0.02 s; last line "
                         "particle_steps_per_s=<value>");
  cl.add_option("--threads", "N", "OpenMP threads (default: OMP_NUM_THREADS or all cores)");
  cl.add_option("--end-time", "T", "simulated time, s", "0.02");
  cl.add_option("--spacing", "DP", "particle spacing, m", "0.0085");
  if (!cl.parse(args))
    return 0;
  if (cl.has("--threads"))
    omp_set_num_threads(int(cl.get_int("--threads")));

  using Vector = Eigen::Vector3d;
  sph::CaseDescription<3> c;
  auto& p = c.fluid;
  p.particle_spacing = cl.get_double("--spacing");
  p.smoothing_coefficient = 1.0; // h = sqrt(3) dp
  p.reference_density = 1000;
  p.gravity = Vector(0, 0, -9.81);
  c.sound_coefficient = 20;
  p.viscosity = sph::ViscosityModel::artificial;
  p.artificial_viscosity = 0.1;
  p.density_diffusion = sph::DensityDiffusionModel::none;
  p.scheme = sph::TimeScheme::verlet;
  p.verlet_euler_every = 40;
  p.cfl = 0.2;
  c.fluid_blocks.push_back({Vector(0, 0, 0), Vector(0.4, 0.67, 0.3)});
  c.tank.min = Vector(0, 0, 0);
  c.tank.max = Vector(1.6, 0.67, 0.4);
  c.tank.model = sph::WallModel::dummy_particles;
  c.tank.layers = 1;
  // The column: its top and four sides, outward (the fluid outside).
  sph::WallSurface<3> column;
  column.name = "column";
  column.model = sph::WallModel::dummy_particles;
  column.dummy_layers = 1;
  const Vector lo(0.9, 0.24, 0), size(0.12, 0.12, 0.45);
  for (int k = 0; k < 8; ++k)
    column.vertices.push_back(
        lo + Vector(size[0] * (k & 1), size[1] * ((k >> 1) & 1), size[2] * (k >> 2)));
  const int quads[5][4] = {{4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads)
  {
    column.faces.push_back({q[0], q[1], q[2]});
    column.faces.push_back({q[0], q[2], q[3]});
  }
  c.walls.push_back(column);
  auto fluid = sph::build_fluid(c);
  time_fluid(*fluid, cl.get_double("--end-time"),
             "DualSPHysics CaseDambreak (3D), dp " + std::to_string(p.particle_spacing) + " m");
  return 0;
}
} // namespace chipflex::bench
