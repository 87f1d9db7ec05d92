#pragma once
// Dummy (boundary) particles of a wall, the field's usual alternative to a wall force:
// layers of particles behind the surface whose density follows the continuity equation
// and whose pressure then repels the fluid (dynamic boundary condition, Crespo et al.
// 2007, as in DualSPHysics). Each dummy particle is attached to one face by its
// barycentric weights and its offset along the normal: moving the vertices moves it
// rigidly with the face, and the fluid's force on it goes back to the vertices with
// the same weights (momentum conserving, the moment too for a rigid face).

#include "sph/wall_surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace chipflex::sph
{
template <int dim>
struct WallAttachment
{
  static constexpr std::uint32_t no_wall = 0xffffffffu;
  std::uint32_t wall = no_wall, face = 0;
  std::array<double, dim> weights{};
  double offset = 0;
};

/// Barycentric weights of the points of a lattice about dp apart on one face (2D: the
/// midpoints of n equal pieces, n = length / dp; 3D: the centroids of the n(n+1)/2
/// upright ones of the n^2 sub-triangles, n = sqrt(2 area) / dp), in a fixed order;
/// `f(weights)` is called for each. The dummy layers are these points moved along the
/// face normal. In 3D n follows the area, so that a wall carries about one point per dp^2
/// as the fluid's lattice does (exactly for the right triangles of a quad split dp x dp):
/// n from the longest edge, as before, put twice to three and a half times that on a
/// quad mesh (a 1 mm quad split in two at dp 0.75 mm got 6 points, not 1.8), and the 3D
/// coolant stood off such walls. Every face still gets a point, so a mesh finer than dp
/// stays denser than the lattice, but no hole is wider than a face.
template <int dim, class F>
void for_face_lattice(const WallSurface<dim>& wall, int face, double dp, F&& f)
{
  const auto& v = wall.faces[face];
  if constexpr (dim == 2)
  {
    const int n =
        std::max(1, int(std::lround((wall.vertices[v[1]] - wall.vertices[v[0]]).norm() / dp)));
    for (int s = 0; s < n; ++s)
    {
      const double t = (s + 0.5) / n;
      f(std::array<double, 2>{1 - t, t});
    }
  }
  else
  {
    const auto &a = wall.vertices[v[0]], &b = wall.vertices[v[1]], &c = wall.vertices[v[2]];
    const double twice_area = (b - a).cross(c - a).norm();
    const int n = std::max(1, int(std::lround(std::sqrt(twice_area) / dp)));
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j)
      {
        const double u = (i + 1.0 / 3) / n, w = (j + 1.0 / 3) / n;
        f(std::array<double, 3>{1 - u - w, u, w});
      }
  }
}

/// Layers at offsets -(l + 1/2) dp behind every face (l < layers), dp apart along the
/// face; points closer than dp/2 to an earlier one (convex corners) are dropped.
template <int dim>
std::vector<Eigen::Matrix<double, dim, 1>> generate_dummy_particles(const WallSurface<dim>& wall,
                                                                    double dp, int layers);

/// Attaches a point to the face whose plane it is nearest to among the faces its
/// foot point falls on (or, failing that, the nearest face centre).
template <int dim>
WallAttachment<dim> attach_to_wall(const WallSurface<dim>& wall, std::uint32_t wall_id,
                                   const Eigen::Matrix<double, dim, 1>& x);

/// Position and velocity of an attached particle for the wall's current vertices.
template <int dim>
void attached_state(const WallSurface<dim>& wall, const WallAttachment<dim>& a,
                    Eigen::Matrix<double, dim, 1>& x, Eigen::Matrix<double, dim, 1>& v);
} // namespace chipflex::sph
