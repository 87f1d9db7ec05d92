#pragma once
// A bounding-volume hierarchy over wall faces, for the nearest face to a point. The thin
// skins ask it for every particle near a skin in every step; a chip's skin has hundreds of
// faces within a kernel's reach of a point, so testing them all (the neighbour-grid bins)
// costs more than the force pass. The tree is rebuilt whenever the walls move: a median
// split on the longest axis of the face centres, four faces per leaf, so building is
// O(n log n) and a query visits O(log n) boxes and a few faces.

#include "sph/wall_geometry.h"
#include "sph/wall_surface.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace chipflex::sph
{
template <int dim>
class FaceTree
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  using Face = WallFace;

  /// Builds the tree over the faces of walls[w] (nullptr: left out).
  void build(const std::vector<const WallSurface<dim>*>& walls)
  {
    walls_ = walls;
    faces_.clear();
    nodes_.clear();
    for (std::uint32_t w = 0; w < walls.size(); ++w)
      if (walls[w])
        for (std::uint32_t f = 0; f < walls[w]->faces.size(); ++f)
        {
          Item item;
          item.wall = w;
          item.face = f;
          item.centre = Vector::Zero();
          for (int v = 0; v < dim; ++v)
            item.centre += walls[w]->vertices[walls[w]->faces[f][v]] / double(dim);
          faces_.push_back(item);
        }
    if (faces_.empty())
      return;
    nodes_.reserve(4 * faces_.size() / leaf_size + 2);
    nodes_.emplace_back();
    build_node(0, 0, std::uint32_t(faces_.size()));
  }

  bool empty() const { return faces_.empty(); }

  /// The face nearest to x: its wall and face in `nearest` and the nearest point in
  /// `closest`; false when the tree is empty. Within `exact_distance` of x the face found
  /// is the nearest one; beyond it, one at most (1 + slack) times as far as the nearest.
  /// A point millimetres from a chip has hundreds of faces at nearly the same distance;
  /// the slack cuts the search to the few within reach of the bound it leaves.
  bool nearest(const Vector& x, double exact_distance, double slack, Face& nearest,
               ClosestPoint<dim>& closest) const
  {
    if (faces_.empty())
      return false;
    const double exact2 = exact_distance * exact_distance;
    const double shrink = 1 / ((1 + slack) * (1 + slack));
    double best = std::numeric_limits<double>::infinity(), bound = best;
    bool found = false;
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0)
    {
      const Node& node = nodes_[stack[--top]];
      if (box_distance2(node, x) >= bound)
        continue;
      if (node.count > 0)
      {
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k)
        {
          const ClosestPoint<dim> cp =
              closest_point_on_face(*walls_[faces_[k].wall], int(faces_[k].face), x);
          if (cp.distance2 < best)
          {
            best = cp.distance2, nearest = faces_[k], closest = cp, found = true;
            bound = best > exact2 ? best * shrink : best;
          }
        }
        continue;
      }
      // The nearer child is searched first (pushed last), so the farther one is mostly
      // cut off by the bound it leaves.
      std::uint32_t a = node.first, b = node.first + 1;
      if (box_distance2(nodes_[a], x) < box_distance2(nodes_[b], x))
        std::swap(a, b);
      stack[top++] = a;
      stack[top++] = b;
    }
    return found;
  }

private:
  static constexpr std::uint32_t leaf_size = 4;

  struct Node
  {
    Vector lo, hi;
    std::uint32_t first = 0; ///< leaf: first face; inner node: its first child node
    std::uint32_t count = 0; ///< faces in a leaf; 0 for an inner node (two children)
  };

  static double box_distance2(const Node& node, const Vector& x)
  {
    double d2 = 0;
    for (int d = 0; d < dim; ++d)
    {
      const double below = node.lo[d] - x[d], above = x[d] - node.hi[d];
      const double gap = std::max({below, above, 0.0});
      d2 += gap * gap;
    }
    return d2;
  }

  /// Fills node `index` for faces_[first, last); an inner node's two children are stored
  /// next to each other.
  void build_node(std::uint32_t index, std::uint32_t first, std::uint32_t last)
  {
    Vector lo = Vector::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    Vector centre_lo = lo, centre_hi = hi;
    for (std::uint32_t k = first; k < last; ++k)
    {
      const auto& wall = *walls_[faces_[k].wall];
      for (int v = 0; v < dim; ++v)
      {
        const Vector& x = wall.vertices[wall.faces[faces_[k].face][v]];
        lo = lo.cwiseMin(x);
        hi = hi.cwiseMax(x);
      }
      centre_lo = centre_lo.cwiseMin(faces_[k].centre);
      centre_hi = centre_hi.cwiseMax(faces_[k].centre);
    }
    nodes_[index].lo = lo;
    nodes_[index].hi = hi;
    if (last - first <= leaf_size)
    {
      nodes_[index].first = first;
      nodes_[index].count = last - first;
      return;
    }
    int axis = 0;
    (centre_hi - centre_lo).maxCoeff(&axis);
    const std::uint32_t middle = first + (last - first) / 2;
    std::nth_element(faces_.begin() + first, faces_.begin() + middle, faces_.begin() + last,
                     [axis](const Item& a, const Item& b)
                     { return a.centre[axis] < b.centre[axis]; });
    const std::uint32_t children = std::uint32_t(nodes_.size());
    nodes_.emplace_back();
    nodes_.emplace_back();
    nodes_[index].first = children;
    nodes_[index].count = 0;
    build_node(children, first, middle);
    build_node(children + 1, middle, last);
  }

  std::vector<const WallSurface<dim>*> walls_;
  struct Item : Face
  {
    Vector centre;
  };
  std::vector<Item> faces_;
  std::vector<Node> nodes_;
};
} // namespace chipflex::sph
