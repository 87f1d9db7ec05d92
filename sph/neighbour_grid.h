#pragma once
// Cell-linked list over a fixed domain box. Cells are 2h wide (the kernel support), so
// the neighbours of a particle lie in its own and the adjacent cells. Cells are numbered
// x-fastest and the particles of each block are counting-sorted by cell, so the three
// cells (ix-1, ix, ix+1) of one row form ONE contiguous index range: a particle visits
// 3 ranges in 2D and 9 in 3D, all streamed linearly from memory. One ghost cell pads
// every side so that no range needs a bounds check.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace chipflex::sph
{
template <int dim>
class NeighbourGrid
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  static constexpr int n_rows = dim == 2 ? 3 : 9;
  static constexpr std::uint32_t outside = 0xffffffffu;

  void setup(const Vector& domain_min, const Vector& domain_max, double cell_size);

  /// Cell of a point, or `outside` if it is not inside the domain box (NaN included).
  std::uint32_t cell_of(const double* x) const
  {
    std::uint32_t c = 0;
    for (int d = dim - 1; d >= 0; --d)
    {
      const double s = (x[d] - min_[d]) * inverse_cell_size_;
      if (!(s >= 0 && s < interior_[d])) // also false for NaN
        return outside;
      c = c * n_[d] + std::uint32_t(s) + 1;
    }
    return c;
  }

  /// Stable counting sort of cells[first, last): returns in `permutation` the old index
  /// (relative to first) of each new position and fills `start` (n_cells + 1 entries,
  /// absolute indices) so that cell c holds [start[c], start[c+1]).
  void sort(const std::vector<std::uint32_t>& cells, std::size_t first, std::size_t last,
            std::vector<std::uint32_t>& permutation, std::vector<std::uint32_t>& start) const;

  /// Offsets (in cells) from a cell to the first cell of each neighbour row, minus one
  /// in x: row r spans cells [c + row_offset[r], c + row_offset[r] + 3).
  const std::array<std::int64_t, n_rows>& row_offsets() const { return row_offsets_; }
  std::size_t n_cells() const { return n_cells_; }
  double cell_size() const { return cell_size_; }
  /// Cells whose box overlaps [lo, hi] (clamped to the grid), for binning wall faces.
  template <typename F>
  void for_cells_overlapping(const Vector& lo, const Vector& hi, F&& f) const;

private:
  Vector min_;
  double cell_size_ = 0, inverse_cell_size_ = 0;
  std::array<std::uint32_t, dim> n_{}; // cells per direction including ghosts
  std::array<double, dim> interior_{}; // interior cells per direction
  std::array<std::int64_t, n_rows> row_offsets_{};
  std::size_t n_cells_ = 0;
};

template <int dim>
template <typename F>
void NeighbourGrid<dim>::for_cells_overlapping(const Vector& lo, const Vector& hi, F&& f) const
{
  std::array<std::int64_t, dim> a, b;
  for (int d = 0; d < dim; ++d)
  {
    a[d] = std::max<std::int64_t>(
        0, std::int64_t(std::floor((lo[d] - min_[d]) * inverse_cell_size_)) + 1);
    b[d] = std::min<std::int64_t>(
        n_[d] - 1, std::int64_t(std::floor((hi[d] - min_[d]) * inverse_cell_size_)) + 1);
    if (a[d] > b[d])
      return;
  }
  if constexpr (dim == 2)
  {
    for (std::int64_t y = a[1]; y <= b[1]; ++y)
      for (std::int64_t x = a[0]; x <= b[0]; ++x)
        f(std::uint32_t(x + n_[0] * y));
  }
  else
  {
    for (std::int64_t z = a[2]; z <= b[2]; ++z)
      for (std::int64_t y = a[1]; y <= b[1]; ++y)
        for (std::int64_t x = a[0]; x <= b[0]; ++x)
          f(std::uint32_t(x + n_[0] * (y + n_[1] * z)));
  }
}
} // namespace chipflex::sph
