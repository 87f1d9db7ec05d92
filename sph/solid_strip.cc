#include "sph/solid_strip.h"

#include <cmath>
#include <stdexcept>

namespace chipflex::sph
{
SolidSkin build_solid_strip(SolidBody<2>& solid, const SolidStripLayout& layout)
{
  if (!(layout.length > 0 && layout.thickness > 0))
    throw std::invalid_argument("solid strip: the length and the thickness must be given (> 0)");
  const int rows = static_cast<int>(std::lround(layout.length / layout.spacing));
  const int layers = layout.layers;
  if (rows < 2 || layers < 2)
    throw std::invalid_argument("solid strip: at least two rows and two layers needed");
  if (layout.clamp_columns < layers || layout.clamp_rows < 1)
    throw std::invalid_argument("solid strip: the clamp must be at least as wide as the strip");
  const Eigen::Vector2d d = layout.direction.normalized();
  const Eigen::Vector2d n(-d.y(), d.x()); // (d, n) right-handed
  const double ds = layout.length / rows;
  const double dc = layout.thickness / layers;
  const double volume = ds * dc;
  auto place = [&](double s, double c)
  { return Eigen::Vector2d(layout.clamped_end_centre + s * d + c * n); };

  // Deformable particles: index = row * layers + layer; row 0 next to the clamp.
  const int first = static_cast<int>(solid.n_particles());
  auto id = [&](int row, int layer) { return first + row * layers + layer; };
  for (int row = 0; row < rows; ++row)
    for (int layer = 0; layer < layers; ++layer)
      solid.add_particle(place((row + 0.5) * ds, (layer + 0.5) * dc - 0.5 * layout.thickness),
                         volume, false);
  for (int row = 1; row <= layout.clamp_rows; ++row)
    for (int col = 0; col < layout.clamp_columns; ++col)
      solid.add_particle(place((0.5 - row) * ds, (col - 0.5 * (layout.clamp_columns - 1)) * dc),
                         volume, true);

  SolidSkin skin;
  // A skin node on particle p, pushed half a spacing outward along each listed inward
  // neighbour q: x = x_p + 1/2 sum (x_p - x_q).
  auto node = [&](int p, std::initializer_list<int> inward)
  {
    std::vector<std::pair<int, double>> w{{p, 1.0}};
    for (int q : inward)
    {
      w.front().second += 0.5;
      w.push_back({q, -0.5});
    }
    skin.nodes.push_back(std::move(w));
    return static_cast<int>(skin.nodes.size()) - 1;
  };
  const int last = rows - 1, top = layers - 1;
  std::vector<int> order;
  // Side c < 0 from the clamp to the free end (the first node also reaches back to
  // the clamp face so the wall closes against the clamp).
  order.push_back(node(id(0, 0), {id(0, 1), id(1, 0)}));
  for (int row = 1; row < last; ++row)
    order.push_back(node(id(row, 0), {id(row, 1)}));
  order.push_back(node(id(last, 0), {id(last, 1), id(last - 1, 0)}));
  skin.tip_nodes.push_back(order.back());
  for (int layer = 1; layer < top; ++layer)
  {
    order.push_back(node(id(last, layer), {id(last - 1, layer)}));
    skin.tip_nodes.push_back(order.back());
  }
  order.push_back(node(id(last, top), {id(last, top - 1), id(last - 1, top)}));
  skin.tip_nodes.push_back(order.back());
  for (int row = last - 1; row >= 1; --row)
    order.push_back(node(id(row, top), {id(row, top - 1)}));
  order.push_back(node(id(0, top), {id(0, top - 1), id(1, top)}));

  // Traversal: along +s on the c < 0 side, across the free end, back along -s on the
  // c > 0 side — counter-clockwise in the right-handed (s, c) frame, so (dy, -dx) of
  // each face points out of the strip.
  for (std::size_t k = 0; k + 1 < order.size(); ++k)
    skin.faces.push_back({order[k], order[k + 1]});
  return skin;
}
} // namespace chipflex::sph
