#include "sph/lennard_jones_wall.h"

#include "common/input_error.h"
#include "sph/wall_geometry.h"

#include <omp.h>

namespace chipflex::sph
{
LennardJonesParameters derive_lennard_jones(LennardJonesParameters p, double dp, double rho0,
                                            double expected_pressure, const std::string& wall_name)
{
  if (p.r0 == 0)
    p.r0 = 0.5 * dp;
  if (p.R == 0)
    p.R = std::max(dp, 1.5 * p.r0);
  if (p.k == 0)
    p.k = 10 * expected_pressure / (rho0 * dp);
  if (!(p.r0 > 0 && p.R > p.r0 && p.k > 0))
    throw InputError(
        "wall " + wall_name,
        "Lennard-Jones parameters need 0 < r0 < R and k > 0 (got r0 = " + std::to_string(p.r0) +
            ", R = " + std::to_string(p.R) + ", k = " + std::to_string(p.k) + ")");
  return p;
}

template <int dim>
void LennardJonesWalls<dim>::bin(const std::vector<const WallSurface<dim>*>& walls,
                                 const NeighbourGrid<dim>& grid)
{
  walls_ = walls;
  forces_.clear();
  for (std::uint32_t w = 0; w < walls.size(); ++w)
    forces_.emplace_back(walls[w] ? walls[w]->lennard_jones : LennardJonesParameters{1, 2, 1});
  bins_.bin(walls, grid, [&](std::uint32_t w) { return forces_[w].R; });
}

template <int dim>
void LennardJonesWalls<dim>::apply(ParticleArrays<dim>& p, std::size_t first, std::size_t last,
                                   double mass,
                                   std::vector<std::vector<Vector>>& vertex_forces) const
{
  if (bins_.faces.empty())
    return;
  std::vector<std::vector<Contribution>> per_thread(omp_get_max_threads());
#pragma omp parallel if (last - first > parallel_threshold)
  {
    auto& mine = per_thread[omp_get_thread_num()];
    // schedule(static): thread t owns one contiguous, ascending particle block, so
    // concatenating the thread lists in thread order gives the particle order.
#pragma omp for schedule(static)
    for (std::size_t i = first; i < last; ++i)
    {
      const std::uint32_t c = p.cell[i];
      // Over MPI a ghost's owner applies the wall to it (and counts the reaction).
      if (bins_.start[c] == bins_.start[c + 1] || p.is_ghost(i))
        continue;
      Vector x;
      for (int d = 0; d < dim; ++d)
        x[d] = p.position[d][i];
      Vector acc = Vector::Zero();
      // Planes already applied to this particle (wall, normal, offset).
      std::array<std::pair<std::uint32_t, Eigen::Matrix<double, dim + 1, 1>>, 8> planes;
      int n_planes = 0;
      for (std::uint32_t e = bins_.start[c]; e < bins_.start[c + 1]; ++e)
      {
        const typename FaceBins<dim>::Face& f = bins_.faces[bins_.entries[e]];
        const auto& wall = *walls_[f.wall];
        const auto& lj = forces_[f.wall];
        const FaceProjection<dim> proj = project_on_face(wall, f.face, x);
        if (!proj.inside || proj.distance >= lj.R || proj.distance <= -lj.R)
          continue;
        Eigen::Matrix<double, dim + 1, 1> plane;
        plane << proj.normal, proj.normal.dot(x) - proj.distance;
        bool seen = false;
        for (int k = 0; k < n_planes && !seen; ++k)
          seen = planes[k].first == f.wall && (planes[k].second - plane).norm() < 1e-9;
        if (seen)
          continue;
        if (n_planes < int(planes.size()))
          planes[n_planes++] = {f.wall, plane};
        const Vector a = lj(proj.distance) * proj.normal;
        acc += a;
        mine.push_back({f.wall, f.face, proj.weights, a});
      }
      for (int d = 0; d < dim; ++d)
        p.acceleration[d][i] += float(acc[d]);
    }
  }
  for (const auto& list : per_thread)
    for (const auto& c : list)
    {
      const auto& face = walls_[c.wall]->faces[c.face];
      for (int k = 0; k < dim; ++k)
        vertex_forces[c.wall][face[k]] -= (mass * c.weights[k]) * c.force;
    }
}

template class LennardJonesWalls<2>;
template class LennardJonesWalls<3>;
} // namespace chipflex::sph
