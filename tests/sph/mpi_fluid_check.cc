// The fluid over MPI ranks against the one-process run (run it under mpirun -np N).
//
//   mpi_fluid_check CASE END_TIME
//     CASE: dambreak2d  a 0.5 x 1 m column in a 3 m tank, dp 0.02, Verlet, dummy walls
//           box2d       a collapsing block in a closed box, Lennard-Jones walls, symplectic
//                       scheme, particle shifting, laminar viscosity
//           cavity2d    a lid-driven cavity (Re 50) whose lid slides in place: a wall
//                       that reads the fluid's density at mirror points
//           cavity2d_summation  the cavity with the summation density and a background
//                       pressure (the owners' densities move after the exchange)
//           dambreak3d  a small 3D column, dp 0.04, Verlet, dummy walls
//
// While it runs, every 100 steps: the halo holds exactly what it must (every ghost is a
// bitwise copy of its owner's particle, taken after the exchange; every owned particle
// within the halo width of another rank's slab is a ghost there; no rank holds a ghost of
// its own), and every fluid particle is owned by exactly one rank. At the end rank 0
// gathers the fluid, runs the same case in one process and compares:
//   - with one rank: bitwise equal (the exchange changes nothing);
//   - with more: the sums run in another order, so the answers agree to rounding, which
//     the flow then amplifies (the 2D dam break at np 3: 3e-6 dp RMS at 0.1 s, 0.009 dp
//     at 0.3 s): the front (largest x of the fluid) within 0.5 %, the kinetic energy
//     within 0.5 % and the RMS particle displacement below 0.05 dp.
// Exit status 0 when everything holds.

#include "sph/case_setup.h"
#include "sph/particle_exchange.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <mpi.h>
#include <string>
#include <vector>

using namespace chipflex::sph;

namespace
{
int failures = 0;

void check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::printf("FAILED: %s\n", what.c_str());
    ++failures;
  }
}

CaseDescription<2> dam_break_2d()
{
  CaseDescription<2> c;
  auto& p = c.fluid;
  p.particle_spacing = 0.02;
  p.smoothing_coefficient = 1.0;
  p.gravity = Eigen::Vector2d(0, -9.81);
  p.viscosity = ViscosityModel::artificial;
  p.artificial_viscosity = 0.02;
  p.density_diffusion = DensityDiffusionModel::fourtakas;
  p.scheme = TimeScheme::verlet;
  c.sound_coefficient = 10;
  c.fluid_blocks.push_back({Eigen::Vector2d(0, 0), Eigen::Vector2d(0.5, 1)});
  c.tank.min = Eigen::Vector2d(0, 0);
  c.tank.max = Eigen::Vector2d(3, 1.5);
  c.tank.model = WallModel::dummy_particles;
  return c;
}

CaseDescription<2> box_2d()
{
  CaseDescription<2> c;
  auto& p = c.fluid;
  p.particle_spacing = 0.01;
  p.gravity = Eigen::Vector2d(0, -9.81);
  p.speed_of_sound = 20;
  p.viscosity = ViscosityModel::laminar; // the other viscosity model (Lo & Shao 2002)
  p.kinematic_viscosity = 1e-4;
  p.scheme = TimeScheme::symplectic;
  p.density_diffusion = DensityDiffusionModel::molteni_colagrossi;
  p.shifting_coefficient = 2;
  c.fluid_blocks.push_back({Eigen::Vector2d(0, 0), Eigen::Vector2d(0.3, 0.2)});
  c.tank.min = Eigen::Vector2d(0, 0);
  c.tank.max = Eigen::Vector2d(0.8, 0.4);
  c.tank.open_top = false;
  c.tank.model = WallModel::lennard_jones;
  return c;
}

/// A wall that takes its density at mirror points across its face: a lid-driven cavity
/// (Re 50) whose lid slides in place. (No-slip walls, the other such kind, run in
/// tests/sph/mpi_run.sh's channel.)
CaseDescription<2> cavity_2d()
{
  CaseDescription<2> c;
  auto& p = c.fluid;
  const double L = 0.1, dp = 0.0025, U = 0.5;
  p.particle_spacing = dp;
  p.gravity = Eigen::Vector2d::Zero();
  p.speed_of_sound = 20 * U;
  p.viscosity = ViscosityModel::laminar;
  p.kinematic_viscosity = U * L / 50;
  p.scheme = TimeScheme::symplectic;
  c.hydrostatic_start = false;
  c.fluid_blocks.push_back({Eigen::Vector2d(0, 0), Eigen::Vector2d(L, L)});
  c.tank.min = Eigen::Vector2d(0, 0);
  c.tank.max = Eigen::Vector2d(L, L);
  c.tank.open_top = true;
  c.tank.model = WallModel::dummy_particles;
  WallSurface<2> lid;
  lid.name = "lid";
  lid.model = WallModel::dummy_particles;
  lid.vertices = {Eigen::Vector2d(-3 * dp, L), Eigen::Vector2d(L + 3 * dp, L)};
  lid.velocities = {Eigen::Vector2d(U, 0), Eigen::Vector2d(U, 0)};
  lid.faces = {{0, 1}};
  lid.slides_in_place = true;
  c.walls.push_back(lid);
  return c;
}

/// The cavity with its density taken by summation (FluidParameters::summation_blend) and a
/// background pressure: the owners' densities change inside the force pass, after the
/// exchange, so the halo check right after the forces sees whether the ghosts follow.
CaseDescription<2> cavity_2d_summation()
{
  CaseDescription<2> c = cavity_2d();
  c.fluid.summation_blend = 0.1;
  c.fluid.background_pressure =
      0.05 * c.fluid.reference_density * c.fluid.speed_of_sound * c.fluid.speed_of_sound;
  return c;
}

CaseDescription<3> dam_break_3d()
{
  CaseDescription<3> c;
  auto& p = c.fluid;
  p.particle_spacing = 0.04;
  p.smoothing_coefficient = 1.0;
  p.gravity = Eigen::Vector3d(0, 0, -9.81);
  p.viscosity = ViscosityModel::artificial;
  p.artificial_viscosity = 0.1;
  p.scheme = TimeScheme::verlet;
  c.sound_coefficient = 10;
  c.fluid_blocks.push_back({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.4, 0.4, 0.6)});
  c.tank.min = Eigen::Vector3d(0, 0, 0);
  c.tank.max = Eigen::Vector3d(1.6, 0.4, 0.8);
  c.tank.model = WallModel::dummy_particles;
  return c;
}

/// One fluid particle as a rank holds it.
template <int dim>
struct Record
{
  int rank = 0;
  bool ghost = false;
  std::uint32_t id = 0;
  std::array<double, 2 * dim + 1> state{}; // x, v, rho
};

/// Every rank's fluid particles (owned and ghosts), on rank 0.
template <int dim>
std::vector<Record<dim>> gather_fluid(const FluidSolver<dim>& fluid)
{
  constexpr int size = 3 + 2 * dim; // ghost flag, id, x, v, rho
  const auto& p = fluid.particles();
  std::vector<double> mine;
  for (std::size_t i = p.n_boundary; i < p.size(); ++i)
  {
    mine.push_back(p.is_ghost(i) ? 1.0 : 0.0);
    mine.push_back(double(p.id[i]));
    for (int d = 0; d < dim; ++d)
      mine.push_back(p.position[d][i]);
    for (int d = 0; d < dim; ++d)
      mine.push_back(double(p.velocity[d][i]));
    mine.push_back(double(p.density[i]));
  }
  int rank = 0, n_ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &n_ranks);
  int count = int(mine.size());
  std::vector<int> counts(n_ranks), offsets(n_ranks);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  int total = 0;
  for (int r = 0; r < n_ranks; ++r)
    offsets[r] = total, total += counts[r];
  std::vector<double> all(std::size_t(total) + 1);
  mine.push_back(0.0); // never a null buffer
  MPI_Gatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
              0, MPI_COMM_WORLD);
  std::vector<Record<dim>> out;
  if (rank != 0)
    return out;
  for (int r = 0; r < n_ranks; ++r)
    for (int k = offsets[r]; k < offsets[r] + counts[r]; k += size)
    {
      Record<dim> rec;
      rec.rank = r;
      rec.ghost = all[k] != 0.0;
      rec.id = std::uint32_t(all[k + 1]);
      for (int j = 0; j < 2 * dim + 1; ++j)
        rec.state[j] = all[k + 2 + j];
      out.push_back(rec);
    }
  return out;
}

/// Ownership and halo, checked on rank 0 from everything every rank holds.
template <int dim>
void check_halo(const std::vector<Record<dim>>& all, const SlabDecomposition& slabs,
                std::size_t n_expected, double time)
{
  std::map<std::uint32_t, const Record<dim>*> owned;
  std::map<std::pair<int, std::uint32_t>, const Record<dim>*> ghosts;
  bool unique = true, own_ghost = false;
  for (const auto& r : all)
    if (!r.ghost)
      unique = owned.emplace(r.id, &r).second && unique;
  for (const auto& r : all)
    if (r.ghost)
    {
      ghosts.emplace(std::make_pair(r.rank, r.id), &r);
      const auto it = owned.find(r.id);
      own_ghost = own_ghost || it == owned.end() || it->second->rank == r.rank;
    }
  const std::string at = " (t = " + std::to_string(time) + " s)";
  check(unique, "a fluid particle is owned by two ranks" + at);
  check(owned.size() == n_expected, "the ranks own " + std::to_string(owned.size()) +
                                        " fluid particles, not " + std::to_string(n_expected) + at);
  check(!own_ghost, "a ghost without an owner elsewhere" + at);
  std::size_t missing = 0, different = 0, expected_ghosts = 0;
  for (const auto& [id, r] : owned)
  {
    double x[dim];
    for (int d = 0; d < dim; ++d)
      x[d] = r->state[d];
    check(slabs.owner(x) == r->rank, "particle " + std::to_string(id) + " outside its slab" + at);
    slabs.for_each_ghost_rank(x, r->rank,
                              [&](int other)
                              {
                                ++expected_ghosts;
                                const auto g = ghosts.find({other, id});
                                if (g == ghosts.end())
                                  ++missing;
                                else if (g->second->state != r->state)
                                  ++different;
                              });
  }
  check(missing == 0, std::to_string(missing) + " ghosts missing" + at);
  check(different == 0, std::to_string(different) + " ghosts differ from their owner" + at);
  check(ghosts.size() == expected_ghosts, std::to_string(ghosts.size()) + " ghosts, expected " +
                                              std::to_string(expected_ghosts) + at);
}

template <int dim>
int run(const std::string& name, CaseDescription<dim> c, double end_time)
{
  int rank = 0, n_ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &n_ranks);
  CaseDescription<dim> c_reference = c;
  auto fluid = build_fluid(c);
  auto exchange = std::make_shared<ParticleExchange<dim>>();
  exchange->rebalance_every = 50; // the dam break's front moves the load
  fluid->distribute(exchange);
  std::size_t n_checks = 0;
  // Right after the exchange (the forces are computed, the state is not yet advanced).
  fluid->add_hook(HookPoint::after_forces,
                  [&](FluidSolver<dim>& f)
                  {
                    if (f.step_count() % 100 != 1)
                      return;
                    // The run's losses: the same list on every rank.
                    const double lost = double(f.lost_particles().size());
                    const auto all = gather_fluid(f);
                    if (rank == 0)
                      check_halo(all, exchange->decomposition(),
                                 f.n_fluid_created() - std::size_t(lost), f.time());
                    ++n_checks;
                  });
  while (fluid->time() < end_time)
    fluid->step();
  const auto all = gather_fluid(*fluid);
  const auto& stats = exchange->statistics();
  double totals[3] = {double(stats.migrated), double(stats.ghosts), 0};
  MPI_Allreduce(MPI_IN_PLACE, totals, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  totals[2] = double(fluid->lost_particles().size()); // the same on every rank
  if (rank != 0)
    return 0;

  // The one-process run.
  auto reference = build_fluid(c_reference);
  while (reference->time() < end_time)
    reference->step();
  const auto& q = reference->particles();
  std::map<std::uint32_t, std::size_t> at;
  for (std::size_t i = q.n_boundary; i < q.size(); ++i)
    at[q.id[i]] = i;
  double front = -1e30, front_ref = -1e30, ke = 0, ke_ref = 0, sum_dx2 = 0, max_dx = 0;
  std::size_t n = 0, unmatched = 0;
  bool bitwise = true;
  for (const auto& r : all)
  {
    if (r.ghost)
      continue;
    ++n;
    front = std::max(front, r.state[0]);
    for (int d = 0; d < dim; ++d)
      ke += 0.5 * r.state[dim + d] * r.state[dim + d];
    const auto it = at.find(r.id);
    if (it == at.end())
    {
      ++unmatched;
      continue;
    }
    double dx2 = 0;
    for (int d = 0; d < dim; ++d)
    {
      const double dx = r.state[d] - q.position[d][it->second];
      dx2 += dx * dx;
      bitwise = bitwise && r.state[d] == q.position[d][it->second] &&
                r.state[dim + d] == double(q.velocity[d][it->second]);
    }
    bitwise = bitwise && r.state[2 * dim] == double(q.density[it->second]);
    sum_dx2 += dx2;
    max_dx = std::max(max_dx, std::sqrt(dx2));
  }
  for (std::size_t i = q.n_boundary; i < q.size(); ++i)
  {
    front_ref = std::max(front_ref, q.position[0][i]);
    for (int d = 0; d < dim; ++d)
      ke_ref += 0.5 * double(q.velocity[d][i]) * double(q.velocity[d][i]);
  }
  const double dp = c.fluid.particle_spacing;
  const double front_error = std::abs(front - front_ref) / std::abs(front_ref);
  const double ke_error = std::abs(ke - ke_ref) / ke_ref;
  std::printf("case=%s ranks=%d t=%.4f s (one process: %.4f s)\n", name.c_str(), n_ranks,
              fluid->time(), reference->time());
  std::printf("steps=%lld (one process: %lld) halo_checks=%zu\n",
              static_cast<long long>(fluid->step_count()),
              static_cast<long long>(reference->step_count()), n_checks);
  std::printf("fluid=%zu (one process: %zu) lost=%.0f (one process: %zu)\n", n,
              q.size() - q.n_boundary, totals[2], reference->lost_particles().size());
  std::printf("migrated=%.0f ghosts_per_step=%.1f rebalances=%llu\n", totals[0],
              totals[1] / double(std::max<std::int64_t>(1, fluid->step_count())),
              static_cast<unsigned long long>(stats.rebalances));
  std::printf("front=%.6f m (one process %.6f m, error %.3g %%)\n", front, front_ref,
              100 * front_error);
  std::printf("kinetic_energy_per_kg=%.6g (one process %.6g, error %.3g %%)\n", ke, ke_ref,
              100 * ke_error);
  const double rms_dx = std::sqrt(sum_dx2 / double(std::max<std::size_t>(n, 1)));
  std::printf("rms_displacement_dp=%.3g max_displacement_dp=%.3g bitwise=%s\n", rms_dx / dp,
              max_dx / dp, bitwise ? "yes" : "no");
  check(unmatched == 0, std::to_string(unmatched) + " particles unknown to the one-process run");
  check(n_checks > 0, "no halo check ran");
  if (n_ranks == 1)
    check(bitwise, "one rank is not bitwise the one-process run");
  check(front_error < 0.005, "the front differs by more than 0.5 %");
  check(ke_error < 0.005, "the kinetic energy differs by more than 0.5 %");
  check(rms_dx < 0.05 * dp, "the particles moved apart by more than 0.05 dp (RMS)");
  std::printf("%s\n", failures ? "FAILED" : "passed");
  return failures;
}
} // namespace

int main(int argc, char** argv)
{
  MpiSession session;
  if (argc != 3)
  {
    std::fprintf(stderr, "usage: mpi_fluid_check "
                         "dambreak2d|box2d|cavity2d|cavity2d_summation|dambreak3d END_TIME\n");
    return 2;
  }
  const std::string name = argv[1];
  const double end_time = std::atof(argv[2]);
  int status = 2;
  if (name == "dambreak2d")
    status = run<2>(name, dam_break_2d(), end_time);
  else if (name == "box2d")
    status = run<2>(name, box_2d(), end_time);
  else if (name == "cavity2d")
    status = run<2>(name, cavity_2d(), end_time);
  else if (name == "cavity2d_summation")
    status = run<2>(name, cavity_2d_summation(), end_time);
  else if (name == "dambreak3d")
    status = run<3>(name, dam_break_3d(), end_time);
  else
    std::fprintf(stderr, "mpi_fluid_check: unknown case '%s'\n", name.c_str());
  MPI_Allreduce(MPI_IN_PLACE, &status, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return status;
}
