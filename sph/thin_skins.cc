#include "sph/thin_skins.h"

#include "sph/wall_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace chipflex::sph
{
template <int dim>
bool is_closed(const WallSurface<dim>& wall)
{
  if (wall.faces.empty())
    return false;
  // 2D: every vertex ends two segments; 3D: every edge borders two triangles.
  std::map<std::array<int, dim - 1>, int> count;
  for (const auto& f : wall.faces)
  {
    if constexpr (dim == 2)
    {
      ++count[{f[0]}];
      ++count[{f[1]}];
    }
    else
      for (int k = 0; k < 3; ++k)
      {
        const int a = f[k], b = f[(k + 1) % 3];
        ++count[{std::min(a, b), std::max(a, b)}];
      }
  }
  for (const auto& [key, n] : count)
    if (n != 2)
      return false;
  return true;
}

template <int dim>
double skin_thickness(const WallSurface<dim>& wall)
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  if (!is_closed(wall))
    return 0;
  double thinnest = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < wall.faces.size(); ++f)
  {
    Vector centre = Vector::Zero();
    for (int k = 0; k < dim; ++k)
      centre += wall.vertices[wall.faces[f][k]] / double(dim);
    const Vector n = face_normal(wall, int(f));
    for (std::size_t g = 0; g < wall.faces.size(); ++g)
    {
      if (g == f)
        continue;
      const Vector ng = face_normal(wall, int(g));
      const double cosine = ng.dot(n);
      if (std::abs(cosine) < 1e-12)
        continue;
      // The ray centre - t n meets face g's plane at t.
      const double t = ng.dot(centre - wall.vertices[wall.faces[g][0]]) / cosine;
      if (!(t > 0) || t >= thinnest)
        continue;
      const FaceProjection<dim> hit = project_on_face(wall, int(g), Vector(centre - t * n));
      bool on_face = true;
      for (double w : hit.weights)
        on_face = on_face && w >= -1e-9;
      if (on_face)
        thinnest = t;
    }
  }
  return thinnest;
}

template <int dim>
std::vector<WallAttachment<dim>> generate_thin_skin_dummies(const WallSurface<dim>& wall,
                                                            std::uint32_t wall_id, double dp,
                                                            int layers)
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  std::vector<WallAttachment<dim>> out;
  std::vector<Vector> points, served;
  std::map<std::array<long, dim>, std::vector<std::size_t>> buckets;
  auto key = [&](const Vector& x)
  {
    std::array<long, dim> k;
    for (int d = 0; d < dim; ++d)
      k[d] = long(std::floor(x[d] / dp));
    return k;
  };
  // Drops a point within dp/2 of an earlier one that serves the same side (the layers of
  // neighbouring faces overlap at convex corners); the other side's layers may pass.
  auto add = [&](std::uint32_t face, const std::array<double, dim>& weights, double offset)
  {
    const Vector x = point_on_face(wall, int(face), weights, offset);
    const Vector n = (offset < 0 ? 1.0 : -1.0) * face_normal(wall, int(face));
    const auto k = key(x);
    for (int i = 0; i < (dim == 2 ? 9 : 27); ++i)
    {
      auto m = k;
      m[0] += i % 3 - 1;
      m[1] += (i / 3) % 3 - 1;
      if constexpr (dim == 3)
        m[2] += i / 9 - 1;
      const auto it = buckets.find(m);
      if (it != buckets.end())
        for (auto j : it->second)
          if ((points[j] - x).norm() < 0.5 * dp && served[j].dot(n) > 0.5)
            return;
    }
    buckets[k].push_back(points.size());
    points.push_back(x);
    served.push_back(n);
    WallAttachment<dim> a;
    a.wall = wall_id;
    a.face = face;
    a.weights = weights;
    a.offset = offset;
    out.push_back(a);
  };
  const bool both_sides = !is_closed(wall);
  for (std::uint32_t f = 0; f < wall.faces.size(); ++f)
  {
    for (int side = 0; side < (both_sides ? 2 : 1); ++side)
    {
      const double sign = side == 0 ? -1 : 1;
      for (int l = 0; l < layers; ++l)
        for_face_lattice(wall, int(f), dp,
                         [&](const std::array<double, dim>& w)
                         { add(f, w, sign * (l + 0.5) * dp); });
    }
  }
  return out;
}

template <int dim>
void dummy_side(const WallSurface<dim>& wall, const WallAttachment<dim>& a, float (&side)[dim],
                float& skin)
{
  const auto n = face_normal(wall, int(a.face));
  const double sign = a.offset < 0 ? 1 : -1; // behind the face: it serves the front
  for (int d = 0; d < dim; ++d)
    side[d] = float(sign * n[d]);
  skin = float(a.wall + 1);
}

template <int dim>
void ThinSkins<dim>::bin(const std::vector<const WallSurface<dim>*>& walls,
                         const std::vector<char>& closed, const NeighbourGrid<dim>& grid,
                         double reach, double exact_distance)
{
  walls_ = walls;
  closed_ = closed;
  bins_.bin(walls, grid, [reach](std::uint32_t) { return reach; });
  tree_.build(walls);
  exact_distance_ = exact_distance;
}

template <int dim>
bool ThinSkins<dim>::nearest_face(const NeighbourGrid<dim>& grid, const Vector& x, Face& best,
                                  ClosestPoint<dim>& closest) const
{
  // The bins say whether x is within reach of a skin; the tree finds the nearest face.
  const std::uint32_t c = grid.cell_of(x.data());
  if (c == NeighbourGrid<dim>::outside || bins_.start[c] == bins_.start[c + 1])
    return false;
  // Exact within a spacing, where the guard needs the true foot point; farther out the
  // side only has to tell the sides apart (the mask's thresholds are cosines of +-1/2,
  // and a point at most 1.2 times as far as the nearest is seen within 34 degrees).
  return tree_.nearest(x, exact_distance_, 0.2, best, closest);
}

template <int dim>
std::size_t ThinSkins<dim>::label_fluid(ParticleArrays<dim>& p, std::size_t first, std::size_t last,
                                        const NeighbourGrid<dim>& grid, double guard_distance,
                                        double mass, double dt,
                                        std::vector<std::vector<Vector>>& guard_forces)
{
  crossed_.assign(last - first, 0);
  std::size_t n_crossed = 0;
  // The nearest face of the thin skins binned in x's cell: (entry, closest point).
  auto nearest = [&](const Vector& x, Face& best, ClosestPoint<dim>& closest)
  { return nearest_face(grid, x, best, closest); };
#pragma omp parallel for schedule(dynamic, 1024) reduction(+ : n_crossed)                          \
    if (last - first > parallel_threshold)
  for (std::size_t i = first; i < last; ++i)
  {
    Vector x;
    for (int d = 0; d < dim; ++d)
      x[d] = p.position[d][i];
    Face f{};
    ClosestPoint<dim> cp;
    if (!nearest(x, f, cp))
    {
      for (int d = 0; d < dim; ++d)
        p.side[d][i] = 0;
      p.skin[i] = 0;
      continue;
    }
    const double distance = std::sqrt(cp.distance2);
    Vector s = distance > 0 ? Vector((x - cp.point) / distance)
                            : face_normal(*walls_[f.wall], int(f.face));
    const float skin = float(f.wall + 1);
    double facing = 0;
    for (int d = 0; d < dim; ++d)
      facing += double(p.side[d][i]) * s[d];
    if (p.skin[i] == skin && facing < -0.5 && cp.inside)
    {
      crossed_[i - first] = 1; // put back below, in particle order
      ++n_crossed;
      continue;
    }
    for (int d = 0; d < dim; ++d)
      p.side[d][i] = float(s[d]);
    p.skin[i] = skin;
  }
  if (n_crossed == 0)
    return 0;
  std::size_t n_owned = 0;
  for (std::size_t i = first; i < last; ++i)
  {
    if (!crossed_[i - first])
      continue;
    // Over MPI a ghost is put back as its owner puts the particle back (the same state
    // and skins give the same move), but its momentum and count are the owner's.
    const bool ghost = p.is_ghost(i);
    n_owned += !ghost;
    Vector x, old_side;
    for (int d = 0; d < dim; ++d)
      x[d] = p.position[d][i], old_side[d] = p.side[d][i];
    Face k{};
    ClosestPoint<dim> cp;
    nearest(x, k, cp);
    const std::uint32_t w = k.wall;
    Vector n = face_normal(*walls_[w], int(k.face));
    if (closed_[w])
    {
      // A closed skin: back in front of the nearest face that faces the old side (the
      // particle may have passed through the whole skin).
      const std::uint32_t c = grid.cell_of(x.data());
      double best = std::numeric_limits<double>::infinity();
      for (std::uint32_t e = bins_.start[c]; e < bins_.start[c + 1]; ++e)
      {
        const typename FaceBins<dim>::Face& f = bins_.faces[bins_.entries[e]];
        if (f.wall != w || face_normal(*walls_[w], int(f.face)).dot(old_side) <= 0.5)
          continue;
        const ClosestPoint<dim> q = closest_point_on_face(*walls_[w], int(f.face), x);
        if (q.distance2 < best)
          best = q.distance2, k = f, cp = q;
      }
      n = face_normal(*walls_[w], int(k.face));
    }
    else if (n.dot(old_side) < 0)
      n = -n; // towards the side it came from
    const WallSurface<dim>& wall = *walls_[w];
    const auto& face = wall.faces[k.face];
    Vector v_wall = Vector::Zero();
    for (int j = 0; j < dim; ++j)
      v_wall += cp.weights[j] * wall.velocities[face[j]];
    const Vector x_new = cp.point + guard_distance * n;
    Vector dv = Vector::Zero();
    for (int d = 0; d < dim; ++d)
    {
      p.position[d][i] = x_new[d];
      if (!p.position_previous[d].empty())
        p.position_previous[d][i] = x_new[d];
    }
    // Strip the approach towards the face from both velocities the integrators use.
    for (auto* velocity : {&p.velocity, &p.velocity_previous})
    {
      Vector v;
      for (int d = 0; d < dim; ++d)
        v[d] = (*velocity)[d][i];
      const double approach = (v - v_wall).dot(n);
      if (approach < 0)
      {
        const Vector change = -approach * n;
        for (int d = 0; d < dim; ++d)
          (*velocity)[d][i] = float(v[d] + change[d]);
        if (velocity == &p.velocity)
          dv = change;
      }
    }
    for (int d = 0; d < dim; ++d)
      p.side[d][i] = float(n[d]);
    if (dt > 0 && !ghost)
      for (int j = 0; j < dim; ++j)
        guard_forces[k.wall][face[j]] -= cp.weights[j] * mass * dv / dt;
  }
  return n_owned;
}

template <int dim>
void ThinSkins<dim>::label_boundary(ParticleArrays<dim>& p, const NeighbourGrid<dim>& grid,
                                    const std::vector<char>& is_own) const
{
  const std::size_t nb = p.n_boundary;
#pragma omp parallel for schedule(dynamic, 1024) if (nb > parallel_threshold)
  for (std::size_t i = 0; i < nb; ++i)
  {
    if (is_own[p.id[i]])
      continue;
    Vector x;
    for (int d = 0; d < dim; ++d)
      x[d] = p.position[d][i];
    float side[dim] = {}, skin = 0;
    Face k{};
    ClosestPoint<dim> best;
    if (nearest_face(grid, x, k, best))
    {
      const double distance = std::sqrt(best.distance2);
      const Vector s = distance > 0 ? Vector((x - best.point) / distance)
                                    : face_normal(*walls_[k.wall], int(k.face));
      for (int d = 0; d < dim; ++d)
        side[d] = float(s[d]);
      skin = float(k.wall + 1);
    }
    for (int d = 0; d < dim; ++d)
      p.side[d][i] = side[d];
    p.skin[i] = skin;
  }
}

template bool is_closed(const WallSurface<2>&);
template bool is_closed(const WallSurface<3>&);
template double skin_thickness(const WallSurface<2>&);
template double skin_thickness(const WallSurface<3>&);
template std::vector<WallAttachment<2>> generate_thin_skin_dummies(const WallSurface<2>&,
                                                                   std::uint32_t, double, int);
template std::vector<WallAttachment<3>> generate_thin_skin_dummies(const WallSurface<3>&,
                                                                   std::uint32_t, double, int);
template void dummy_side(const WallSurface<2>&, const WallAttachment<2>&, float (&)[2], float&);
template void dummy_side(const WallSurface<3>&, const WallAttachment<3>&, float (&)[3], float&);
template class ThinSkins<2>;
template class ThinSkins<3>;
} // namespace chipflex::sph
