// FluidSolver over MPI ranks: the run's records (losses, largest speed, closest pair) made
// the same on every rank after each step, so that summaries, probes and checkpoints,
// written by rank 0, are the whole run's and every rank stops on the same step; and the
// walls' fluid forces summed over the ranks, so that every rank moves its copy of the
// bodies alike.

#include "sph/fluid_solver_impl.h"
#include "sph/particle_exchange.h"

namespace chipflex::sph
{
template <int dim>
void FluidSolver<dim>::share_run_records()
{
  // One record per rank: its largest speed and closest pair (with when and where), then
  // its losses since the last share: [n, then per loss id, step, cause, time, rho, x].
  constexpr int loss_size = 5 + dim;
  std::vector<double> mine;
  mine.push_back(peak_speed_);
  mine.push_back(peak_speed_time_);
  for (int d = 0; d < dim; ++d)
    mine.push_back(peak_speed_position_[d]);
  mine.push_back(closest_pair_);
  mine.push_back(closest_pair_time_);
  for (int d = 0; d < dim; ++d)
    mine.push_back(closest_pair_position_[d]);
  mine.push_back(double(lost_.size() - lost_shared_));
  for (std::size_t k = lost_shared_; k < lost_.size(); ++k)
  {
    const auto& l = lost_[k];
    mine.insert(mine.end(),
                {double(l.id), double(l.step), double(int(l.cause)), l.time, l.density});
    for (int d = 0; d < dim; ++d)
      mine.push_back(l.position[d]);
  }
  const std::vector<double> all = exchange_->all_gather(mine);
  lost_.resize(lost_shared_);
  // Ranks in order, starting from rank 0's record; on a tie the lowest rank's wins, so
  // every rank keeps the same.
  for (std::size_t at = 0; at < all.size();)
  {
    const bool first = at == 0;
    const double* r = &all[at];
    if (first || r[0] > peak_speed_)
    {
      peak_speed_ = r[0];
      peak_speed_time_ = r[1];
      for (int d = 0; d < dim; ++d)
        peak_speed_position_[d] = r[2 + d];
    }
    r += 2 + dim;
    if (first || r[0] < closest_pair_)
    {
      closest_pair_ = r[0];
      closest_pair_time_ = r[1];
      for (int d = 0; d < dim; ++d)
        closest_pair_position_[d] = r[2 + d];
    }
    r += 2 + dim;
    const std::size_t n_lost = std::size_t(r[0]);
    ++r;
    for (std::size_t k = 0; k < n_lost; ++k, r += loss_size)
    {
      LostParticle<dim> l;
      l.id = std::uint32_t(r[0]);
      l.step = std::int64_t(r[1]);
      l.cause = LossCause(int(r[2]));
      l.time = r[3];
      l.density = r[4];
      for (int d = 0; d < dim; ++d)
        l.position[d] = r[5 + d];
      lost_.push_back(l);
    }
    at = std::size_t(r - all.data());
  }
  lost_shared_ = lost_.size();
}

template <int dim>
void FluidSolver<dim>::sum_vertex_forces_over_ranks()
{
  std::vector<double> flat;
  for (const auto& forces : vertex_forces_)
    for (const auto& f : forces)
      for (int d = 0; d < dim; ++d)
        flat.push_back(f[d]);
  if (flat.empty())
    return;
  exchange_->sum(flat.data(), int(flat.size()));
  std::size_t k = 0;
  for (auto& forces : vertex_forces_)
    for (auto& f : forces)
      for (int d = 0; d < dim; ++d)
        f[d] = flat[k++];
}

template void FluidSolver<2>::share_run_records();
template void FluidSolver<3>::share_run_records();
template void FluidSolver<2>::sum_vertex_forces_over_ranks();
template void FluidSolver<3>::sum_vertex_forces_over_ranks();
} // namespace chipflex::sph
