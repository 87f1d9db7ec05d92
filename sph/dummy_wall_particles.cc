#include "sph/dummy_wall_particles.h"

#include "sph/wall_geometry.h"

#include <cmath>
#include <limits>
#include <map>

namespace chipflex::sph
{
template <int dim>
std::vector<Eigen::Matrix<double, dim, 1>> generate_dummy_particles(const WallSurface<dim>& wall,
                                                                    double dp, int layers)
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  std::vector<Vector> points;
  // Hash on a dp/2 lattice to drop near-duplicates where layers of faces overlap.
  std::map<std::array<long, dim>, std::vector<std::size_t>> buckets;
  auto key = [&](const Vector& x)
  {
    std::array<long, dim> k;
    for (int d = 0; d < dim; ++d)
      k[d] = long(std::floor(x[d] / dp));
    return k;
  };
  // A body thinner than the layers' depth (a 5 mm plate at dp = 4 mm has layers to
  // 14 mm) would get the layers of one face poking out through the opposite face: there
  // they sit in the fluid, push it off the wall by up to a layer depth and, attached to
  // the nearest face, load the body where no water presses on it (the 3D plate under a
  // water column swung with +-50 N against a 1.26 N load). A point generated behind one
  // face that lies on the fluid side of another face above whose face it stands has
  // crossed the body, so it is dropped: the body's dummy particles stay inside it. Faces
  // are binned on a grid of the layers' depth so that only nearby ones are tested.
  const double depth = layers * dp;
  std::map<std::array<long, dim>, std::vector<int>> face_cells;
  auto cell = [&](const Vector& x)
  {
    std::array<long, dim> k;
    for (int d = 0; d < dim; ++d)
      k[d] = long(std::floor(x[d] / depth));
    return k;
  };
  for (std::size_t f = 0; f < wall.faces.size(); ++f)
  {
    Vector lo = wall.vertices[wall.faces[f][0]], hi = lo;
    for (int v = 1; v < dim; ++v)
    {
      lo = lo.cwiseMin(wall.vertices[wall.faces[f][v]]);
      hi = hi.cwiseMax(wall.vertices[wall.faces[f][v]]);
    }
    const auto a = cell(lo - Vector::Constant(depth)), b = cell(hi + Vector::Constant(depth));
    std::array<long, dim> k = a;
    while (true)
    {
      face_cells[k].push_back(int(f));
      int d = 0;
      for (; d < dim; ++d)
      {
        if (++k[d] <= b[d])
          break;
        k[d] = a[d];
      }
      if (d == dim)
        break;
    }
  }
  auto crossed = [&](const Vector& x, std::size_t own)
  {
    const auto it = face_cells.find(cell(x));
    if (it == face_cells.end())
      return false;
    for (int g : it->second)
    {
      if (std::size_t(g) == own)
        continue;
      const FaceProjection<dim> p = project_on_face(wall, g, x);
      if (p.inside && p.distance > 0)
        return true;
    }
    return false;
  };
  auto add = [&](const Vector& x, std::size_t own)
  {
    if (crossed(x, own))
      return;
    const auto k = key(x);
    for (int i = 0; i < (dim == 2 ? 9 : 27); ++i)
    {
      auto n = k;
      n[0] += i % 3 - 1;
      n[1] += (i / 3) % 3 - 1;
      if constexpr (dim == 3)
        n[2] += i / 9 - 1;
      auto it = buckets.find(n);
      if (it != buckets.end())
        for (auto j : it->second)
          if ((points[j] - x).norm() < 0.5 * dp)
            return;
    }
    buckets[k].push_back(points.size());
    points.push_back(x);
  };
  for (std::size_t f = 0; f < wall.faces.size(); ++f)
    for (int l = 0; l < layers; ++l)
      for_face_lattice(wall, int(f), dp,
                       [&](const std::array<double, dim>& w)
                       { add(point_on_face(wall, int(f), w, -(l + 0.5) * dp), f); });
  return points;
}

template <int dim>
WallAttachment<dim> attach_to_wall(const WallSurface<dim>& wall, std::uint32_t wall_id,
                                   const Eigen::Matrix<double, dim, 1>& x)
{
  WallAttachment<dim> best;
  best.wall = wall_id;
  double best_score = std::numeric_limits<double>::max();
  for (std::size_t f = 0; f < wall.faces.size(); ++f)
  {
    const FaceProjection<dim> p = project_on_face(wall, int(f), x);
    // Outside a face, add the distance of the weights from the face so that corner
    // particles go to the face they are the closest extension of.
    double outside = 0;
    for (double w : p.weights)
      outside += std::max(0.0, -w);
    const double score =
        std::abs(p.distance) + 1e3 * outside * (p.inside ? 0 : 1) + (p.inside ? 0 : 1e-9);
    if (score < best_score)
    {
      best_score = score;
      best.face = std::uint32_t(f);
      best.weights = p.weights;
      best.offset = p.distance;
    }
  }
  return best;
}

template <int dim>
void attached_state(const WallSurface<dim>& wall, const WallAttachment<dim>& a,
                    Eigen::Matrix<double, dim, 1>& x, Eigen::Matrix<double, dim, 1>& v)
{
  x = point_on_face(wall, int(a.face), a.weights, a.offset);
  v.setZero();
  const auto& face = wall.faces[a.face];
  if (!wall.velocities.empty())
    for (int k = 0; k < dim; ++k)
      v += a.weights[k] * wall.velocities[face[k]];
}

template std::vector<Eigen::Matrix<double, 2, 1>> generate_dummy_particles(const WallSurface<2>&,
                                                                           double, int);
template std::vector<Eigen::Matrix<double, 3, 1>> generate_dummy_particles(const WallSurface<3>&,
                                                                           double, int);
template WallAttachment<2> attach_to_wall(const WallSurface<2>&, std::uint32_t,
                                          const Eigen::Matrix<double, 2, 1>&);
template WallAttachment<3> attach_to_wall(const WallSurface<3>&, std::uint32_t,
                                          const Eigen::Matrix<double, 3, 1>&);
template void attached_state(const WallSurface<2>&, const WallAttachment<2>&,
                             Eigen::Matrix<double, 2, 1>&, Eigen::Matrix<double, 2, 1>&);
template void attached_state(const WallSurface<3>&, const WallAttachment<3>&,
                             Eigen::Matrix<double, 3, 1>&, Eigen::Matrix<double, 3, 1>&);
} // namespace chipflex::sph
