// FluidSolver over MPI ranks: the run's records (losses, largest speed, closest pair) made
// the same on every rank after each step, so that summaries, probes and checkpoints,
// written by rank 0, are the whole run's and every rank stops on the same step; and the
// walls' fluid forces summed over the ranks, so that every rank moves its copy of the
// bodies alike; the open boundaries' counts summed and their new particles numbered
// across the ranks; and the halo width that the walls and buffers need.

#include "sph/fluid_solver_impl.h"
#include "sph/particle_exchange.h"
#include "sph/wall_geometry.h"

#include <algorithm>
#include <cmath>

namespace chipflex::sph
{
template <int dim>
void FluidSolver<dim>::share_run_records()
{
  // One record per rank: its largest speed and closest pairs (with when and where), the
  // fluid particles its thin skins' guard put back since the last share, then its losses
  // since the last share: [n, then per loss id, step, cause, time, rho, x].
  constexpr int loss_size = 5 + dim;
  std::vector<double> mine;
  mine.push_back(peak_speed_);
  mine.push_back(peak_speed_time_);
  for (int d = 0; d < dim; ++d)
    mine.push_back(peak_speed_position_[d]);
  for (const auto* pair : {&closest_pair_, &closest_skin_pair_})
  {
    mine.push_back(pair->distance);
    mine.push_back(pair->time);
    for (int d = 0; d < dim; ++d)
      mine.push_back(pair->position[d]);
  }
  mine.push_back(tension_peak_);
  mine.push_back(tension_peak_time_);
  mine.push_back(lowest_absolute_pressure_);
  mine.push_back(double(impl_->n_guarded - impl_->n_guarded_shared));
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
  impl_->n_guarded = impl_->n_guarded_shared;
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
    for (auto* pair : {&closest_pair_, &closest_skin_pair_})
    {
      if (first || r[0] < pair->distance)
      {
        pair->distance = r[0];
        pair->time = r[1];
        for (int d = 0; d < dim; ++d)
          pair->position[d] = r[2 + d];
      }
      r += 2 + dim;
    }
    // Each rank's fraction of its own fluid: the largest is at least the whole fluid's.
    if (first || r[0] > tension_peak_)
    {
      tension_peak_ = r[0];
      tension_peak_time_ = r[1];
    }
    lowest_absolute_pressure_ = first ? r[2] : std::min(lowest_absolute_pressure_, r[2]);
    r += 3;
    impl_->n_guarded += std::size_t(r[0]);
    ++r;
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
  impl_->n_guarded_shared = impl_->n_guarded;
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

template <int dim>
HaloNeeds<dim> FluidSolver<dim>::exchange_halo_needs() const
{
  const auto& im = *impl_;
  const double cell = im.grid.cell_size();
  // The fluid a rank's own particles see, and the fluid that the wall particles they see
  // (those within a cell of the slab) sum over.
  HaloNeeds<dim> needs;
  needs.width = Vector::Constant(2 * cell);
  // Walls that take their velocity or density at a mirror point across their face: a
  // wall particle within a cell of the slab reads the fluid within 2h of a point 2 d away
  // along the face's normal, d its depth. Along the slab axis that is 2 d |n_axis| for a
  // wall that keeps its faces (one that does not move, or slides in place); a body's may
  // turn, so its particles count with |n_axis| = 1.
  const bool mirrored =
      parameters_.no_slip_walls ||
      std::any_of(walls_.begin(), walls_.end(), [](const auto& w) { return w.slides_in_place; });
  if (mirrored)
  {
    Vector reach = Vector::Zero();
    for (const auto& a : im.attachments)
    {
      if (a.wall == WallAttachment<dim>::no_wall)
        continue;
      const auto& wall = walls_[a.wall];
      const bool keeps_faces = !wall.moves || wall.slides_in_place;
      const Vector along =
          keeps_faces ? Vector(2 * std::abs(a.offset) * face_normal(wall, int(a.face)).cwiseAbs())
                      : Vector::Constant(2 * std::abs(a.offset));
      reach = reach.cwiseMax(along);
    }
    needs.width = needs.width.cwiseMax(Vector(reach.array() + cell + 2 * h_));
  }
  // An open boundary's buffer particle reads the fluid within 2h of its mirror point, up
  // to twice the buffer's thickness further along the zone's axis: the ranks whose slab
  // holds part of a buffer need that much (its ghosts take the owner's values).
  for (const auto& zone : zones_)
    needs.wide.push_back(
        {zone.axis,
         {zone.box_min[zone.axis], zone.box_max[zone.axis], 2 * zone.thickness() + 2 * h_}});
  return needs;
}

template <int dim>
std::size_t FluidSolver<dim>::share_open_boundary_counts(std::size_t n_births,
                                                         const std::vector<std::int64_t>& created,
                                                         const std::vector<std::int64_t>& removed)
{
  const std::size_t nz = zones_.size();
  std::vector<double> mine{double(n_births)};
  for (std::size_t k = 0; k < nz; ++k)
    mine.push_back(double(created[k]));
  for (std::size_t k = 0; k < nz; ++k)
    mine.push_back(double(removed[k]));
  const std::vector<double> all = exchange_->all_gather(mine);
  const std::size_t record = 1 + 2 * nz;
  std::size_t first_id = n_fluid_created_;
  for (int r = 0; r < exchange_->n_ranks(); ++r)
  {
    const double* in = &all[std::size_t(r) * record];
    if (r < exchange_->rank())
      first_id += std::size_t(in[0]);
    n_fluid_created_ += std::size_t(in[0]);
    for (std::size_t k = 0; k < nz; ++k)
    {
      zone_created_[k] += std::int64_t(in[1 + k]);
      zone_removed_[k] += std::int64_t(in[1 + nz + k]);
    }
  }
  return first_id;
}

template void FluidSolver<2>::share_run_records();
template void FluidSolver<3>::share_run_records();
template void FluidSolver<2>::sum_vertex_forces_over_ranks();
template void FluidSolver<3>::sum_vertex_forces_over_ranks();
template HaloNeeds<2> FluidSolver<2>::exchange_halo_needs() const;
template HaloNeeds<3> FluidSolver<3>::exchange_halo_needs() const;
template std::size_t FluidSolver<2>::share_open_boundary_counts(std::size_t,
                                                                const std::vector<std::int64_t>&,
                                                                const std::vector<std::int64_t>&);
template std::size_t FluidSolver<3>::share_open_boundary_counts(std::size_t,
                                                                const std::vector<std::int64_t>&,
                                                                const std::vector<std::int64_t>&);
} // namespace chipflex::sph
