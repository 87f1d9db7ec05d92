// ParticleExchange: migration and ghosts of the fluid over MPI ranks, with plain MPI
// collectives (MPI_Alltoallv): a slab has at most two neighbours, but the collective also
// serves empty slabs, slabs thinner than the halo and the set-up without special cases.

#include "sph/particle_exchange.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <limits>
#include <mpi.h>
#include <stdexcept>
#include <string>

namespace chipflex::sph
{
namespace
{
using Clock = std::chrono::steady_clock;

/// Whether MpiSession's exit handler calls MPI_Finalize (not after an error).
bool finalise_at_exit = false;

double seconds_since(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// What travels at the end of every particle record where the case has open boundaries
/// or thin skins (ParticleExchange::initialise decides, alike on every rank): the zone
/// flags, the thin-skin id and side.
template <int dim>
constexpr int tag_size = 2 + dim;
/// A migrating particle: id, x, v, v_previous, rho, rho_previous, fill, the last force
/// pass's acceleration and density rate (the position-Verlet predictor uses them), tags.
template <int dim>
constexpr int migrant_tags_at = 5 + 4 * dim;
template <int dim>
constexpr int largest_migrant_size = migrant_tags_at<dim> + tag_size<dim>;
template <int dim>
int migrant_size(bool tags)
{
  return migrant_tags_at<dim> + (tags ? tag_size<dim> : 0);
}
/// A ghost: id, x, v, rho, fill, tags.
template <int dim>
constexpr int ghost_tags_at = 3 + 2 * dim;
template <int dim>
int ghost_size(bool tags)
{
  return ghost_tags_at<dim> + (tags ? tag_size<dim> : 0);
}

/// A wall particle's state that only the rank owning its position computes right:
/// density, previous density, density rate, and velocity (a no-slip wall's is taken from
/// the fluid at its mirror point).
template <int dim>
constexpr std::size_t wall_state_size = 3 + dim;

template <int dim>
void pack_tags(const ParticleArrays<dim>& p, std::size_t i, double* out)
{
  out[0] = p.zone.empty() ? 0.0 : double(p.zone[i]);
  out[1] = p.skin.empty() ? 0.0 : double(p.skin[i]);
  for (int d = 0; d < dim; ++d)
    out[2 + d] = p.skin.empty() ? 0.0 : double(p.side[d][i]);
}

template <int dim>
void unpack_tags(const double* in, ParticleArrays<dim>& p, std::size_t i)
{
  if (!p.zone.empty())
    p.zone[i] = std::uint8_t(in[0]);
  if (!p.skin.empty())
  {
    p.skin[i] = float(in[1]);
    for (int d = 0; d < dim; ++d)
      p.side[d][i] = float(in[2 + d]);
  }
}

template <int dim>
void pack_ghost(const ParticleArrays<dim>& p, std::size_t i, double* out, bool tags)
{
  out[0] = double(p.id[i]);
  for (int d = 0; d < dim; ++d)
  {
    out[1 + d] = p.position[d][i];
    out[1 + dim + d] = double(p.velocity[d][i]);
  }
  out[1 + 2 * dim] = double(p.density[i]);
  out[2 + 2 * dim] = double(p.fill[i]);
  if (tags)
    pack_tags(p, i, out + ghost_tags_at<dim>);
}

template <int dim>
void unpack_ghost(const double* in, ParticleArrays<dim>& p, std::size_t i, bool tags)
{
  for (int d = 0; d < dim; ++d)
  {
    p.position[d][i] = in[1 + d];
    p.velocity[d][i] = p.velocity_previous[d][i] = float(in[1 + dim + d]);
  }
  p.density[i] = p.density_previous[i] = float(in[1 + 2 * dim]);
  p.fill[i] = float(in[2 + 2 * dim]);
  if (tags)
    unpack_tags(in + ghost_tags_at<dim>, p, i);
}

/// Appends a fluid particle with the state of a migrant (or ghost) record.
template <int dim>
void append_record(const double* in, bool migrant, std::uint32_t halo, ParticleArrays<dim>& p,
                   bool tags)
{
  double x[dim];
  float v[dim];
  for (int d = 0; d < dim; ++d)
  {
    x[d] = in[1 + d];
    v[d] = float(in[1 + dim + d]);
  }
  const int rho_at = migrant ? 1 + 3 * dim : 1 + 2 * dim;
  p.append(x, v, float(in[rho_at]), std::uint32_t(in[0]), 0);
  const std::size_t i = p.size() - 1;
  if (migrant)
    for (int d = 0; d < dim; ++d)
      p.velocity_previous[d][i] = float(in[1 + 2 * dim + d]);
  p.density_previous[i] = float(in[migrant ? rho_at + 1 : rho_at]);
  p.fill[i] = float(in[rho_at + (migrant ? 2 : 1)]);
  if (migrant)
  {
    for (int d = 0; d < dim; ++d)
      p.acceleration[d][i] = float(in[4 + 3 * dim + d]);
    p.density_rate[i] = float(in[4 + 4 * dim]);
  }
  if (tags)
    unpack_tags(in + (migrant ? migrant_tags_at<dim> : ghost_tags_at<dim>), p, i);
  if (!p.halo.empty())
    p.halo[i] = halo;
}

template <int dim>
void pack_migrant(const ParticleArrays<dim>& p, std::size_t i, double* out, bool tags)
{
  out[0] = double(p.id[i]);
  for (int d = 0; d < dim; ++d)
  {
    out[1 + d] = p.position[d][i];
    out[1 + dim + d] = double(p.velocity[d][i]);
    out[1 + 2 * dim + d] = double(p.velocity_previous[d][i]);
  }
  out[1 + 3 * dim] = double(p.density[i]);
  out[2 + 3 * dim] = double(p.density_previous[i]);
  out[3 + 3 * dim] = double(p.fill[i]);
  for (int d = 0; d < dim; ++d)
    out[4 + 3 * dim + d] = double(p.acceleration[d][i]);
  out[4 + 4 * dim] = double(p.density_rate[i]);
  if (tags)
    pack_tags(p, i, out + migrant_tags_at<dim>);
}
} // namespace

bool launched_on_several_ranks()
{
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"})
    if (const char* value = std::getenv(name))
      if (std::atoi(value) > 1)
        return true;
  return false;
}

MpiSession::MpiSession()
{
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised)
  {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    // MPI_Finalize at exit, after what was set up later has been torn down (exit handlers
    // and static objects go in the reverse order of their making): the fe body kind's
    // PETSc session finalises PETSc at exit, which needs MPI still up.
    finalise_at_exit = true;
    std::atexit(
        []
        {
          int finalised = 0;
          MPI_Finalized(&finalised);
          if (finalise_at_exit && !finalised)
            MPI_Finalize();
        });
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &n_ranks_);
}

MpiSession::~MpiSession()
{
  // Unwinding from an error on this rank: the others may wait in a collective, and
  // MPI_Finalize would wait for them. Leaving without it, after `main` has printed the
  // error, makes mpirun end the whole job.
  if (std::uncaught_exceptions() > 0)
    finalise_at_exit = false;
}

template <int dim>
ParticleExchange<dim>::ParticleExchange()
{
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised)
    throw std::logic_error("ParticleExchange: MPI is not initialised (MpiSession)");
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &n_ranks_);
}

template <int dim>
void ParticleExchange<dim>::initialise(ParticleArrays<dim>& p, const Vector& domain_min,
                                       const Vector& domain_max, double cell_size,
                                       const HaloNeeds<dim>& halo)
{
  // The longest extent of the particles, fluid and walls (a tank or a channel bounds where
  // the fluid goes), not of the domain box, which is often padded for splashes upwards.
  Vector lo = Vector::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int d = 0; d < dim; ++d)
    {
      lo[d] = std::min(lo[d], p.position[d][i]);
      hi[d] = std::max(hi[d], p.position[d][i]);
    }
  int axis = 0;
  for (int d = 1; d < dim; ++d)
    if (hi[d] - lo[d] > hi[axis] - lo[axis])
      axis = d;
  origin_ = domain_min[axis];
  layer_width_ = cell_size;
  // Every rank holds the whole case here, so all decide alike.
  tags_ = !p.zone.empty() || !p.skin.empty();
  n_layers_ = std::size_t(std::ceil((domain_max[axis] - domain_min[axis]) / cell_size));
  n_layers_ = std::max<std::size_t>(n_layers_, 1);
  // Every rank holds the whole fluid here: its own histogram is the global one.
  std::vector<double> per_layer(n_layers_, 0);
  add_to_histogram(p, axis, p.n_boundary, p.size(), 1.0, per_layer);
  add_to_histogram(p, axis, 0, p.n_boundary, wall_weight, per_layer);
  const double halo_width = halo.width[axis];
  if (!(halo_width >= 2 * cell_size))
    throw std::invalid_argument("ParticleExchange: the halo must span at least two cells");
  std::vector<WideHalo> wide;
  for (const auto& [along, stretch] : halo.wide)
    if (along == axis)
      wide.push_back(stretch);
  slabs_ = SlabDecomposition(
      axis, SlabDecomposition::balanced_cuts(per_layer, origin_, layer_width_, n_ranks_),
      halo_width, wide);
  calls_ = 0;
  n_ghosts_ = 0;
  p.halo.assign(p.size(), 0);
  std::vector<std::size_t> others;
  for (std::size_t i = p.n_boundary; i < p.size(); ++i)
    if (const int owner = owner_of(p, i); owner >= 0 && owner != rank_)
      others.push_back(i);
  p.remove(others);
}

template <int dim>
int ParticleExchange<dim>::owner_of(const ParticleArrays<dim>& p, std::size_t i) const
{
  double x[dim];
  for (int d = 0; d < dim; ++d)
    x[d] = p.position[d][i];
  return slabs_.owner(x);
}

template <int dim>
std::vector<double> ParticleExchange<dim>::all_to_all(const std::vector<std::vector<double>>& send,
                                                      std::vector<int>* received_counts) const
{
  std::vector<int> send_count(n_ranks_), send_offset(n_ranks_), receive_count(n_ranks_),
      receive_offset(n_ranks_);
  std::vector<double> flat;
  for (int r = 0; r < n_ranks_; ++r)
  {
    send_count[r] = int(send[r].size());
    send_offset[r] = int(flat.size());
    flat.insert(flat.end(), send[r].begin(), send[r].end());
  }
  MPI_Alltoall(send_count.data(), 1, MPI_INT, receive_count.data(), 1, MPI_INT, MPI_COMM_WORLD);
  int total = 0;
  for (int r = 0; r < n_ranks_; ++r)
  {
    receive_offset[r] = total;
    total += receive_count[r];
  }
  std::vector<double> received(std::size_t(total) + 1); // +1: never a null buffer
  flat.push_back(0.0);
  MPI_Alltoallv(flat.data(), send_count.data(), send_offset.data(), MPI_DOUBLE, received.data(),
                receive_count.data(), receive_offset.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  received.pop_back();
  if (received_counts)
    *received_counts = receive_count;
  return received;
}

template <int dim>
std::vector<double> ParticleExchange<dim>::global_histogram(const ParticleArrays<dim>& p) const
{
  std::vector<double> per_layer(n_layers_, 0);
  add_to_histogram(p, slabs_.axis(), p.n_boundary, p.size(), 1.0, per_layer);
  MPI_Allreduce(MPI_IN_PLACE, per_layer.data(), int(n_layers_), MPI_DOUBLE, MPI_SUM,
                MPI_COMM_WORLD);
  // Every rank holds every wall particle: added after the sum, once.
  add_to_histogram(p, slabs_.axis(), 0, p.n_boundary, wall_weight, per_layer);
  return per_layer;
}

template <int dim>
void ParticleExchange<dim>::add_to_histogram(const ParticleArrays<dim>& p, int axis,
                                             std::size_t first, std::size_t last, double weight,
                                             std::vector<double>& per_layer) const
{
  for (std::size_t i = first; i < last; ++i)
  {
    const double s = (p.position[axis][i] - origin_) / layer_width_;
    if (!p.is_ghost(i) && std::isfinite(s))
      per_layer[std::size_t(std::clamp(s, 0.0, double(n_layers_ - 1)))] += weight;
  }
}

template <int dim>
void ParticleExchange<dim>::rebalance(const ParticleArrays<dim>& p)
{
  const auto per_layer = global_histogram(p);
  const auto load = slabs_.loads(per_layer, origin_, layer_width_);
  double total = 0, busiest = 0;
  for (const auto l : load)
    total += l, busiest = std::max(busiest, l);
  // Every rank sees the same histogram, so all take the same decision.
  if (double(busiest) * n_ranks_ <= 1.05 * double(total))
    return;
  slabs_ = SlabDecomposition(
      slabs_.axis(), SlabDecomposition::balanced_cuts(per_layer, origin_, layer_width_, n_ranks_),
      slabs_.halo_width(), slabs_.wide_halos());
  ++statistics_.rebalances;
}

template <int dim>
std::vector<double> ParticleExchange<dim>::wall_states(const ParticleArrays<dim>& p,
                                                       const SlabDecomposition& slabs,
                                                       bool everywhere) const
{
  const std::size_t nb = p.n_boundary;
  constexpr std::size_t size = wall_state_size<dim>;
  std::vector<double> values(size * nb + 1, 0.0);
  for (std::size_t i = 0; i < nb; ++i)
  {
    double x[dim];
    for (int d = 0; d < dim; ++d)
      x[d] = p.position[d][i];
    if (slabs.owner(x) == rank_)
    {
      double* out = &values[size * i];
      out[0] = double(p.density[i]);
      out[1] = double(p.density_previous[i]);
      out[2] = double(p.density_rate[i]);
      for (int d = 0; d < dim; ++d)
        out[3 + d] = double(p.velocity[d][i]);
    }
  }
  // Exactly one rank contributes each value: the sum is that value.
  if (everywhere)
    MPI_Allreduce(MPI_IN_PLACE, values.data(), int(size * nb), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  else
    MPI_Reduce(rank_ == 0 ? MPI_IN_PLACE : values.data(), values.data(), int(size * nb), MPI_DOUBLE,
               MPI_SUM, 0, MPI_COMM_WORLD);
  return values;
}

template <int dim>
void ParticleExchange<dim>::set_wall_states(const std::vector<double>& values,
                                            ParticleArrays<dim>& p)
{
  constexpr std::size_t size = wall_state_size<dim>;
  for (std::size_t i = 0; i < p.n_boundary; ++i)
  {
    const double* in = &values[size * i];
    p.density[i] = float(in[0]);
    p.density_previous[i] = float(in[1]);
    p.density_rate[i] = float(in[2]);
    for (int d = 0; d < dim; ++d)
      p.velocity[d][i] = float(in[3 + d]);
  }
}

template <int dim>
void ParticleExchange<dim>::synchronise_walls(ParticleArrays<dim>& p, const SlabDecomposition& old)
{
  set_wall_states(wall_states(p, old, true), p);
}

template <int dim>
void ParticleExchange<dim>::migrate(ParticleArrays<dim>& p)
{
  const int size = migrant_size<dim>(tags_);
  std::vector<std::vector<double>> send(n_ranks_);
  std::vector<std::size_t> leaving;
  for (std::size_t i = p.n_boundary; i < p.size(); ++i)
  {
    const int owner = owner_of(p, i);
    if (owner < 0 || owner == rank_)
      continue;
    double record[largest_migrant_size<dim>];
    pack_migrant(p, i, record, tags_);
    send[owner].insert(send[owner].end(), record, record + size);
    leaving.push_back(i);
  }
  const std::vector<double> arriving = all_to_all(send);
  p.remove(leaving);
  for (std::size_t k = 0; k < arriving.size(); k += size)
    append_record<dim>(&arriving[k], true, 0, p, tags_);
  statistics_.migrated += arriving.size() / size;
}

template <int dim>
void ParticleExchange<dim>::build_ghosts(ParticleArrays<dim>& p)
{
  const int size = ghost_size<dim>(tags_);
  std::vector<std::vector<double>> send(n_ranks_);
  entry_first_.assign(1, 0);
  entry_rank_.clear();
  entry_slot_.clear();
  for (std::size_t i = p.n_boundary; i < p.size(); ++i)
  {
    double x[dim];
    for (int d = 0; d < dim; ++d)
      x[d] = p.position[d][i];
    slabs_.for_each_ghost_rank(x, rank_,
                               [&](int r)
                               {
                                 entry_rank_.push_back(r);
                                 entry_slot_.push_back(std::uint32_t(send[r].size() / size));
                                 send[r].resize(send[r].size() + size);
                                 pack_ghost(p, i, &send[r][send[r].size() - size], tags_);
                               });
    if (entry_rank_.size() > entry_first_.back())
    {
      p.halo[i] = std::uint32_t(entry_first_.size()); // entry k + 1
      entry_first_.push_back(std::uint32_t(entry_rank_.size()));
    }
  }
  send_counts_.assign(n_ranks_, 0);
  for (int r = 0; r < n_ranks_; ++r)
    send_counts_[r] = int(send[r].size() / size);
  const std::vector<double> received = all_to_all(send);
  n_ghosts_ = received.size() / size;
  for (std::size_t j = 0; j < n_ghosts_; ++j)
    append_record<dim>(&received[j * size], false,
                       ParticleArrays<dim>::ghost_flag + std::uint32_t(j), p, tags_);
  statistics_.ghosts += n_ghosts_;
}

template <int dim>
void ParticleExchange<dim>::exchange(ParticleArrays<dim>& p)
{
  const auto t0 = Clock::now();
  std::vector<std::size_t> ghosts;
  for (std::size_t i = p.n_boundary; i < p.size(); ++i)
  {
    if (p.is_ghost(i))
      ghosts.push_back(i);
    else
      p.halo[i] = 0;
  }
  p.remove(ghosts);
  migrate(p);
  if (++calls_ % std::uint64_t(std::max(rebalance_every, 1)) == 0)
  {
    const SlabDecomposition old = slabs_;
    rebalance(p);
    if (statistics_.rebalances != old_rebalances_)
    {
      old_rebalances_ = statistics_.rebalances;
      synchronise_walls(p, old);
      migrate(p);
    }
  }
  const auto t1 = Clock::now();
  statistics_.migration_seconds += std::chrono::duration<double>(t1 - t0).count();
  build_ghosts(p);
  statistics_.halo_seconds += seconds_since(t1);
}

template <int dim>
void ParticleExchange<dim>::refresh_ghosts(ParticleArrays<dim>& p, bool keep_lost)
{
  const auto t0 = Clock::now();
  const int size = ghost_size<dim>(tags_);
  // A slot whose particle was removed since (lost) stays NaN: its ghost is dropped at the
  // next sort without being counted as lost here.
  std::vector<std::vector<double>> send(n_ranks_);
  for (int r = 0; r < n_ranks_; ++r)
    send[r].assign(std::size_t(send_counts_[r]) * size, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = p.n_boundary; i < p.size(); ++i)
  {
    const std::uint32_t h = p.halo[i];
    if (h == 0 || h >= ParticleArrays<dim>::ghost_flag)
      continue;
    for (std::uint32_t e = entry_first_[h - 1]; e < entry_first_[h]; ++e)
      pack_ghost(p, i, &send[entry_rank_[e]][std::size_t(entry_slot_[e]) * size], tags_);
  }
  const std::vector<double> received = all_to_all(send);
  if (received.size() != n_ghosts_ * size)
    throw std::logic_error("ParticleExchange: the ghosts changed within a step");
  for (std::size_t i = p.n_boundary; i < p.size(); ++i)
    if (p.is_ghost(i))
    {
      const double* record =
          &received[std::size_t(p.halo[i] - ParticleArrays<dim>::ghost_flag) * size];
      if (!keep_lost || !std::isnan(record[1]))
        unpack_ghost(record, p, i, tags_);
    }
  statistics_.halo_seconds += seconds_since(t0);
}

template <int dim>
void ParticleExchange<dim>::maximum(double* values, int n)
{
  const auto t0 = Clock::now();
  MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  statistics_.reduction_seconds += seconds_since(t0);
}

template <int dim>
void ParticleExchange<dim>::sum(double* values, int n) const
{
  MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}

template <int dim>
std::vector<double> ParticleExchange<dim>::all_gather(const std::vector<double>& mine) const
{
  int count = int(mine.size());
  std::vector<int> counts(n_ranks_), offsets(n_ranks_);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  int total = 0;
  for (int r = 0; r < n_ranks_; ++r)
  {
    offsets[r] = total;
    total += counts[r];
  }
  std::vector<double> all(std::size_t(total) + 1); // +1: never a null buffer
  std::vector<double> send(mine);
  send.push_back(0.0);
  MPI_Allgatherv(send.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
                 MPI_DOUBLE, MPI_COMM_WORLD);
  all.pop_back();
  return all;
}

template <int dim>
ParticleArrays<dim> ParticleExchange<dim>::own_rows(const ParticleArrays<dim>& p) const
{
  // The wall states: each rank computes only those near its slab, so each wall
  // particle's comes from the rank that owns its position.
  const std::size_t nb = p.n_boundary;
  const std::vector<double> walls = wall_states(p, slabs_, false);
  ParticleArrays<dim> rows = p;
  rows.resize(rank_ == 0 ? nb : 0, !p.position_previous[0].empty(), !p.zone.empty(),
              !p.skin.empty());
  if (rank_ == 0)
    set_wall_states(walls, rows);
  else
    rows.n_boundary = 0;
  double record[largest_migrant_size<dim>];
  for (std::size_t i = nb; i < p.size(); ++i)
    if (!p.is_ghost(i))
    {
      pack_migrant(p, i, record, tags_);
      append_record<dim>(record, true, 0, rows, tags_);
    }
  return rows;
}

template <int dim>
ParticleArrays<dim> ParticleExchange<dim>::gather(const ParticleArrays<dim>& p) const
{
  ParticleArrays<dim> whole = own_rows(p);
  const int size = migrant_size<dim>(tags_);
  std::vector<double> own;
  if (rank_ != 0) // rank 0's own fluid is in `whole` already
    for (std::size_t i = p.n_boundary; i < p.size(); ++i)
      if (!p.is_ghost(i))
      {
        own.resize(own.size() + size);
        pack_migrant(p, i, &own[own.size() - size], tags_);
      }
  int count = int(own.size());
  std::vector<int> counts(n_ranks_), offsets(n_ranks_);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  int total = 0;
  for (int r = 0; r < n_ranks_; ++r)
  {
    offsets[r] = total;
    total += counts[r];
  }
  std::vector<double> all(rank_ == 0 ? std::size_t(total) + 1 : 1);
  own.push_back(0.0);
  MPI_Gatherv(own.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
              0, MPI_COMM_WORLD);
  if (rank_ != 0)
    return {};
  for (int k = 0; k < total; k += size)
    append_record<dim>(&all[std::size_t(k)], true, 0, whole, tags_);
  return whole;
}

template class ParticleExchange<2>;
template class ParticleExchange<3>;
} // namespace chipflex::sph
