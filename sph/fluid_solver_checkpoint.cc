// FluidSolver: checkpoints. Everything that determines the future of the run is saved
// bit for bit (floats widen to double exactly and narrow back exactly), in the current
// (sorted) particle order, so that a restarted run repeats the uninterrupted one.

#include "common/hdf5_file.h"
#include "common/input_error.h"
#include "sph/fluid_solver_impl.h"
#include "sph/particle_exchange.h"

#include <algorithm>

namespace chipflex::sph
{
namespace
{
/// A closest-pair record as attributes NAME, NAME_time, NAME_position_d (none before
/// its first check).
template <int dim>
void write_closest_pair(Hdf5File& file, const std::string& group, const std::string& name,
                        const ClosestPairRecord<dim>& pair)
{
  if (!pair.seen())
    return;
  file.write_attribute(group, name, pair.distance);
  file.write_attribute(group, name + "_time", pair.time);
  for (int d = 0; d < dim; ++d)
    file.write_attribute(group, name + "_position_" + std::to_string(d), pair.position[d]);
}

template <int dim>
ClosestPairRecord<dim> read_closest_pair(const Hdf5File& file, const std::string& group,
                                         const std::string& name)
{
  ClosestPairRecord<dim> pair;
  if (!file.has_attribute(group, name))
    return pair;
  pair.distance = file.read_double_attribute(group, name);
  pair.time = file.read_double_attribute(group, name + "_time");
  for (int d = 0; d < dim; ++d)
    if (const std::string at = name + "_position_" + std::to_string(d);
        file.has_attribute(group, at)) // not in checkpoints older than the position
      pair.position[d] = file.read_double_attribute(group, at);
  return pair;
}

template <typename T>
std::vector<double> widen(const std::vector<T>& a)
{
  return std::vector<double>(a.begin(), a.end());
}

template <typename T, std::size_t D>
std::vector<double> interleave(const std::array<std::vector<T>, D>& a, std::size_t n)
{
  std::vector<double> out(n * D);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t d = 0; d < D; ++d)
      out[i * D + d] = double(a[d][i]);
  return out;
}

template <typename T, std::size_t D>
void split(const std::vector<double>& in, std::array<std::vector<T>, D>& a, std::size_t n,
           const std::string& where)
{
  if (in.size() != n * D)
    throw InputError(where, "wrong size in checkpoint");
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t d = 0; d < D; ++d)
      a[d][i] = T(in[i * D + d]);
}
} // namespace

template <int dim>
void FluidSolver<dim>::save(Hdf5File* file_pointer, const std::string& group) const
{
  const_cast<FluidSolver*>(this)->finish_setup();
  // Over MPI the whole fluid, gathered on rank 0; the run's records are every rank's
  // already (share_run_records).
  const ParticleArrays<dim> gathered =
      exchange_ ? exchange_->gather(particles_) : ParticleArrays<dim>{};
  if (!file_pointer)
    return;
  Hdf5File& file = *file_pointer;
  const auto& p = exchange_ ? gathered : particles_;
  const std::size_t n = p.size();
  file.ensure_group(group);
  file.write_attribute(group, "dim", std::int64_t(dim));
  file.write_attribute(group, "time", time_);
  file.write_attribute(group, "dt", dt_);
  file.write_attribute(group, "step", std::int64_t(step_));
  file.write_attribute(group, "verlet_counter", std::int64_t(verlet_counter_));
  file.write_attribute(group, "n_particles", std::int64_t(n));
  file.write_attribute(group, "n_boundary", std::int64_t(p.n_boundary));
  file.write(group + "/position", interleave(p.position, n), {n, std::size_t(dim)});
  file.write(group + "/velocity", interleave(p.velocity, n), {n, std::size_t(dim)});
  file.write(group + "/velocity_previous", interleave(p.velocity_previous, n),
             {n, std::size_t(dim)});
  if (!p.position_previous[0].empty())
    file.write(group + "/position_previous", interleave(p.position_previous, n),
               {n, std::size_t(dim)});
  file.write(group + "/density", widen(p.density), {n});
  file.write(group + "/density_previous", widen(p.density_previous), {n});
  file.write(group + "/id", std::vector<std::int64_t>(p.id.begin(), p.id.end()), {n});
  file.write(group + "/fill", widen(p.fill), {n});
  // The removed particles: their count decides when the run stops, their log the summary.
  file.write_attribute(group, "n_fluid_created", std::int64_t(n_fluid_created_));
  file.write_attribute(group, "peak_fluid_speed", peak_speed_);
  file.write_attribute(group, "peak_fluid_speed_time", peak_speed_time_);
  for (int d = 0; d < dim; ++d)
    file.write_attribute(group, "peak_fluid_speed_position_" + std::to_string(d),
                         peak_speed_position_[d]);
  write_closest_pair(file, group, "closest_fluid_pair", closest_pair_);
  write_closest_pair(file, group, "closest_skin_side_pair", closest_skin_pair_);
  if (parameters_.background_pressure > 0)
  {
    file.write_attribute(group, "tension_peak_fraction", tension_peak_);
    file.write_attribute(group, "tension_peak_time", tension_peak_time_);
    file.write_attribute(group, "lowest_absolute_pressure", lowest_absolute_pressure_);
    file.write_attribute(group, "tension_mean", tension_mean_);
    file.write_attribute(group, "tension_mean_time", tension_mean_time_);
  }
  const std::size_t nl = lost_.size();
  file.write_attribute(group, "n_lost", std::int64_t(nl));
  if (nl > 0)
  {
    std::vector<std::int64_t> lost_id(nl), lost_step(nl), lost_cause(nl);
    std::vector<double> lost_time(nl), lost_density(nl), lost_x(nl * dim);
    for (std::size_t k = 0; k < nl; ++k)
    {
      lost_id[k] = lost_[k].id;
      lost_step[k] = lost_[k].step;
      lost_cause[k] = std::int64_t(lost_[k].cause);
      lost_time[k] = lost_[k].time;
      lost_density[k] = lost_[k].density;
      for (int d = 0; d < dim; ++d)
        lost_x[k * dim + d] = lost_[k].position[d];
    }
    file.write(group + "/lost/id", lost_id, {nl});
    file.write(group + "/lost/step", lost_step, {nl});
    file.write(group + "/lost/cause", lost_cause, {nl});
    file.write(group + "/lost/time", lost_time, {nl});
    file.write(group + "/lost/density", lost_density, {nl});
    file.write(group + "/lost/position", lost_x, {nl, std::size_t(dim)});
  }
  if (!zones_.empty())
  {
    // Open boundaries: which particles are buffer, and the counts (the ids of new
    // particles continue from n_fluid_created).
    file.write(group + "/zone", std::vector<std::int64_t>(p.zone.begin(), p.zone.end()), {n});
    file.write(group + "/open_boundaries/created", zone_created_, {zones_.size()});
    file.write(group + "/open_boundaries/removed", zone_removed_, {zones_.size()});
  }
  if (!p.skin.empty())
  {
    // Thin skins: the side each particle was on (the guard compares the next one with it).
    file.write(group + "/side", interleave(p.side, n), {n, std::size_t(dim)});
    file.write(group + "/skin", widen(p.skin), {n});
    file.write_attribute(group, "n_guarded", std::int64_t(impl_->n_guarded));
  }
  if (parameters_.scheme == TimeScheme::position_verlet && forces_current_)
  {
    // The next step's predictor and dt come from the last pass: a restart must not
    // recompute them (bitwise equal to the uninterrupted run).
    file.write(group + "/acceleration", interleave(p.acceleration, n), {n, std::size_t(dim)});
    file.write(group + "/density_rate", widen(p.density_rate), {n});
    file.write_attribute(group, "acceleration_max", acceleration_max_);
    file.write_attribute(group, "dot_rr2_max", double(dot_rr2_max_));
  }
  for (std::size_t w = 0; w < walls_.size(); ++w)
  {
    const std::string g = group + "/walls/" + std::to_string(w);
    const std::size_t nv = walls_[w].vertices.size();
    std::vector<double> x(nv * dim), v(nv * dim);
    for (std::size_t k = 0; k < nv; ++k)
      for (int d = 0; d < dim; ++d)
      {
        x[k * dim + d] = walls_[w].vertices[k][d];
        v[k * dim + d] = walls_[w].velocities[k][d];
      }
    file.write(g + "/vertices", x, {nv, std::size_t(dim)});
    file.write(g + "/velocities", v, {nv, std::size_t(dim)});
  }
}

template <int dim>
void FluidSolver<dim>::load(const Hdf5File& file, const std::string& group)
{
  finish_setup();
  auto& p = particles_;
  const std::string where = file.path() + ":" + group;
  if (file.read_integer_attribute(group, "dim") != dim)
    throw InputError(where, "checkpoint of a different dimension");
  // Open boundaries: the inlets' particles are the case's fluid plus what they created.
  const bool zones_saved = file.exists(group + "/zone");
  if (zones_saved != !zones_.empty())
    throw InputError(where, zones_.empty() ? "checkpoint has open boundaries, the case has none"
                                           : "checkpoint has no open boundaries, the case has");
  std::vector<std::int64_t> created(zones_.size(), 0), removed(zones_.size(), 0);
  if (zones_saved)
  {
    created = file.read_integers(group + "/open_boundaries/created");
    removed = file.read_integers(group + "/open_boundaries/removed");
    if (created.size() != zones_.size() || removed.size() != zones_.size())
      throw InputError(where, "checkpoint has another number of open boundaries than the case");
  }
  std::size_t inflow = 0, outflow = 0;
  for (std::size_t k = 0; k < zones_.size(); ++k)
    inflow += std::size_t(created[k]), outflow += std::size_t(removed[k]);
  n_fluid_created_ = n_fluid_initial_ + inflow;
  // Removed fluid particles make the saved count smaller than the case's plus the inflow,
  // never larger.
  const std::size_t n = std::size_t(file.read_integer_attribute(group, "n_particles"));
  if (n > n_fluid_created_ + p.n_boundary ||
      std::size_t(file.read_integer_attribute(group, "n_boundary")) != p.n_boundary)
    throw InputError(where, "checkpoint has a different particle count than the case (" +
                                std::to_string(n_fluid_created_ + p.n_boundary) + " particles, " +
                                std::to_string(p.n_boundary) + " boundary)");
  p.resize(n, is_symplectic(parameters_.scheme), !zones_.empty(), has_thin_skins());
  if (file.exists(group + "/position_previous") != !p.position_previous[0].empty())
    throw InputError(where, "checkpoint was written with another time scheme");
  time_ = file.read_double_attribute(group, "time");
  dt_ = file.read_double_attribute(group, "dt");
  step_ = file.read_integer_attribute(group, "step");
  verlet_counter_ = int(file.read_integer_attribute(group, "verlet_counter"));
  split(file.read_doubles(group + "/position"), p.position, n, where);
  split(file.read_doubles(group + "/velocity"), p.velocity, n, where);
  split(file.read_doubles(group + "/velocity_previous"), p.velocity_previous, n, where);
  if (!p.position_previous[0].empty())
    split(file.read_doubles(group + "/position_previous"), p.position_previous, n, where);
  const auto rho = file.read_doubles(group + "/density");
  const auto rho_prev = file.read_doubles(group + "/density_previous");
  const auto id = file.read_integers(group + "/id");
  // Older checkpoints have no kernel-support filling: treat every particle as fluid.
  const auto fill = file.exists(group + "/fill") ? file.read_doubles(group + "/fill")
                                                 : std::vector<double>(n, 1.0);
  if (rho.size() != n || rho_prev.size() != n || id.size() != n || fill.size() != n)
    throw InputError(where, "wrong array size in checkpoint");
  for (std::size_t i = 0; i < n; ++i)
  {
    p.density[i] = float(rho[i]);
    p.density_previous[i] = float(rho_prev[i]);
    p.id[i] = std::uint32_t(id[i]);
    p.fill[i] = float(fill[i]);
  }
  if (zones_saved)
  {
    const auto zone = file.read_integers(group + "/zone");
    if (zone.size() != n)
      throw InputError(where, "wrong array size in checkpoint");
    for (std::size_t i = 0; i < n; ++i)
    {
      if (zone[i] < 0 || zone[i] > 0xff || std::size_t(zone[i] & zone_index_mask) > zones_.size() ||
          (zone[i] && i < p.n_boundary))
        throw InputError(where, "checkpoint names an open boundary the case has not");
      p.zone[i] = std::uint8_t(zone[i]);
    }
  }
  if (!p.skin.empty())
  {
    if (!file.exists(group + "/skin"))
      throw InputError(where, "checkpoint was written without the case's thin skins");
    split(file.read_doubles(group + "/side"), p.side, n, where);
    const auto skin = file.read_doubles(group + "/skin");
    if (skin.size() != n)
      throw InputError(where, "wrong array size in checkpoint");
    for (std::size_t i = 0; i < n; ++i)
      p.skin[i] = float(skin[i]);
    impl_->n_guarded = impl_->n_guarded_shared =
        std::size_t(file.read_integer_attribute(group, "n_guarded"));
  }
  zone_created_ = created;
  zone_removed_ = removed;
  lost_.clear();
  peak_speed_ = peak_speed_time_ = 0;
  peak_speed_position_.setZero();
  closest_pair_ = read_closest_pair<dim>(file, group, "closest_fluid_pair");
  closest_skin_pair_ = read_closest_pair<dim>(file, group, "closest_skin_side_pair");
  tension_peak_ = tension_peak_time_ = tension_mean_ = tension_mean_time_ = 0;
  lowest_absolute_pressure_ = std::numeric_limits<double>::infinity();
  if (file.has_attribute(group, "tension_peak_fraction"))
  {
    tension_peak_ = file.read_double_attribute(group, "tension_peak_fraction");
    tension_peak_time_ = file.read_double_attribute(group, "tension_peak_time");
    lowest_absolute_pressure_ = file.read_double_attribute(group, "lowest_absolute_pressure");
    tension_mean_ = file.read_double_attribute(group, "tension_mean");
    tension_mean_time_ = file.read_double_attribute(group, "tension_mean_time");
  }
  if (file.has_attribute(group, "n_lost"))
  {
    if (std::size_t(file.read_integer_attribute(group, "n_fluid_created")) != n_fluid_created_)
      throw InputError(where, "checkpoint was written for another fluid set-up");
    peak_speed_ = file.read_double_attribute(group, "peak_fluid_speed");
    peak_speed_time_ = file.read_double_attribute(group, "peak_fluid_speed_time");
    for (int d = 0; d < dim; ++d)
      if (file.has_attribute(group, "peak_fluid_speed_position_" + std::to_string(d)))
        peak_speed_position_[d] =
            file.read_double_attribute(group, "peak_fluid_speed_position_" + std::to_string(d));
    const std::size_t nl = std::size_t(file.read_integer_attribute(group, "n_lost"));
    if (n + nl + outflow != n_fluid_created_ + p.n_boundary)
      throw InputError(where, "particle and lost-particle counts do not add up");
    if (nl > 0)
    {
      const auto lost_id = file.read_integers(group + "/lost/id");
      const auto lost_step = file.read_integers(group + "/lost/step");
      const auto lost_cause = file.read_integers(group + "/lost/cause");
      const auto lost_time = file.read_doubles(group + "/lost/time");
      const auto lost_x = file.read_doubles(group + "/lost/position");
      const auto lost_density = file.read_doubles(group + "/lost/density");
      if (lost_id.size() != nl || lost_step.size() != nl || lost_cause.size() != nl ||
          lost_time.size() != nl || lost_density.size() != nl || lost_x.size() != nl * dim)
        throw InputError(where, "wrong size of the lost-particle log");
      lost_.resize(nl);
      for (std::size_t k = 0; k < nl; ++k)
      {
        lost_[k].id = std::uint32_t(lost_id[k]);
        lost_[k].step = lost_step[k];
        lost_[k].cause = LossCause(std::clamp<std::int64_t>(lost_cause[k], 0, 2));
        lost_[k].time = lost_time[k];
        lost_[k].density = lost_density[k];
        for (int d = 0; d < dim; ++d)
          lost_[k].position[d] = lost_x[k * dim + d];
      }
    }
  }
  else if (n + outflow != n_fluid_created_ + p.n_boundary)
    throw InputError(where, "checkpoint has a different particle count than the case");
  forces_current_ = false;
  if (parameters_.scheme == TimeScheme::position_verlet && file.exists(group + "/acceleration"))
  {
    split(file.read_doubles(group + "/acceleration"), p.acceleration, n, where);
    const auto rate = file.read_doubles(group + "/density_rate");
    if (rate.size() != n)
      throw InputError(where, "wrong array size in checkpoint");
    for (std::size_t i = 0; i < n; ++i)
      p.density_rate[i] = float(rate[i]);
    acceleration_max_ = file.read_double_attribute(group, "acceleration_max");
    dot_rr2_max_ = float(file.read_double_attribute(group, "dot_rr2_max"));
    forces_current_ = true;
  }
  for (std::size_t w = 0; w < walls_.size(); ++w)
  {
    const std::string g = group + "/walls/" + std::to_string(w);
    const auto x = file.read_doubles(g + "/vertices");
    const auto v = file.read_doubles(g + "/velocities");
    const std::size_t nv = walls_[w].vertices.size();
    if (x.size() != nv * dim || v.size() != nv * dim)
      throw InputError(where, "wall " + std::to_string(w) + " has another vertex count");
    for (std::size_t k = 0; k < nv; ++k)
      for (int d = 0; d < dim; ++d)
      {
        walls_[w].vertices[k][d] = x[k * dim + d];
        walls_[w].velocities[k][d] = v[k * dim + d];
      }
  }
  boundary_moved_ = walls_moved_ = true;
  // Over MPI every rank has read the whole fluid: cut it again for this run's ranks.
  if (exchange_)
  {
    exchange_->initialise(p, parameters_.domain_min, parameters_.domain_max,
                          impl_->grid.cell_size(), exchange_halo_needs());
    lost_shared_ = lost_.size();
  }
}

template void FluidSolver<2>::save(Hdf5File*, const std::string&) const;
template void FluidSolver<3>::save(Hdf5File*, const std::string&) const;
template void FluidSolver<2>::load(const Hdf5File&, const std::string&);
template void FluidSolver<3>::load(const Hdf5File&, const std::string&);
} // namespace chipflex::sph
