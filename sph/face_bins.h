#pragma once
// Wall faces binned on the neighbour grid: a compressed cell -> faces table (built in two
// passes, count and fill) holding each face in every cell its box, widened by a margin,
// overlaps. The Lennard-Jones walls (margin: their cut-off R) and the thin skins (margin:
// the kernel support plus the dummy layers' depth) look faces up by a particle's cell.

#include "sph/neighbour_grid.h"
#include "sph/wall_surface.h"

#include <cstdint>
#include <vector>

namespace chipflex::sph
{
template <int dim>
struct FaceBins
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  using Face = WallFace;
  std::vector<Face> faces;                   ///< every face of the walls binned
  std::vector<std::uint32_t> start, entries; ///< cell c holds faces[entries[start[c] ...]]

  /// Bins the faces of walls[w] (nullptr: left out), widened by margin(w).
  template <class Margin>
  void bin(const std::vector<const WallSurface<dim>*>& walls, const NeighbourGrid<dim>& grid,
           Margin&& margin)
  {
    faces.clear();
    for (std::uint32_t w = 0; w < walls.size(); ++w)
      if (walls[w])
        for (std::uint32_t f = 0; f < walls[w]->faces.size(); ++f)
          faces.push_back({w, f});
    start.assign(grid.n_cells() + 1, 0);
    entries.clear();
    if (faces.empty())
      return;
    auto for_each = [&](auto&& f)
    {
      for (std::uint32_t k = 0; k < faces.size(); ++k)
      {
        const auto& wall = *walls[faces[k].wall];
        const auto& face = wall.faces[faces[k].face];
        Vector lo = wall.vertices[face[0]], hi = lo;
        for (int v = 1; v < dim; ++v)
        {
          lo = lo.cwiseMin(wall.vertices[face[v]]);
          hi = hi.cwiseMax(wall.vertices[face[v]]);
        }
        const double m = margin(faces[k].wall);
        grid.for_cells_overlapping(lo.array() - m, hi.array() + m,
                                   [&](std::uint32_t c) { f(c, k); });
      }
    };
    for_each([&](std::uint32_t c, std::uint32_t) { ++start[c + 1]; });
    for (std::size_t c = 0; c + 1 < start.size(); ++c)
      start[c + 1] += start[c];
    entries.resize(start.back());
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for_each([&](std::uint32_t c, std::uint32_t k) { entries[next[c]++] = k; });
  }
};
} // namespace chipflex::sph
