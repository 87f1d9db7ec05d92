#include "sph/neighbour_grid.h"

#include "common/input_error.h"

#include <cmath>
#include <string>

namespace chipflex::sph
{
template <int dim>
void NeighbourGrid<dim>::setup(const Vector& domain_min, const Vector& domain_max, double cell_size)
{
  min_ = domain_min;
  cell_size_ = cell_size;
  inverse_cell_size_ = 1.0 / cell_size;
  n_cells_ = 1;
  for (int d = 0; d < dim; ++d)
  {
    if (!(domain_max[d] > domain_min[d]))
      throw InputError("domain", "the maximum corner must lie above the minimum corner");
    interior_[d] = std::ceil((domain_max[d] - domain_min[d]) * inverse_cell_size_);
    n_[d] = std::uint32_t(interior_[d]) + 2;
    n_cells_ *= n_[d];
  }
  if (n_cells_ > (std::size_t(1) << 31))
    throw InputError("domain", "too many neighbour cells (" + std::to_string(n_cells_) +
                                   "): shrink the domain or enlarge the particle spacing");
  if constexpr (dim == 2)
  {
    for (int r = 0; r < 3; ++r)
      row_offsets_[r] = std::int64_t(r - 1) * n_[0] - 1;
  }
  else
  {
    int k = 0;
    for (int z = -1; z <= 1; ++z)
      for (int y = -1; y <= 1; ++y)
        row_offsets_[k++] = (std::int64_t(z) * n_[1] + y) * n_[0] - 1;
  }
}

template <int dim>
void NeighbourGrid<dim>::sort(const std::vector<std::uint32_t>& cells, std::size_t first,
                              std::size_t last, std::vector<std::uint32_t>& permutation,
                              std::vector<std::uint32_t>& start) const
{
  // Sequential on purpose: O(n) with a tiny constant, and the resulting order (and so
  // every later summation order) cannot depend on the thread count.
  start.assign(n_cells_ + 1, 0);
  for (std::size_t i = first; i < last; ++i)
    ++start[cells[i] + 1];
  start[0] = std::uint32_t(first);
  for (std::size_t c = 0; c < n_cells_; ++c)
    start[c + 1] += start[c];
  permutation.resize(last - first);
  std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
  for (std::size_t i = first; i < last; ++i)
    permutation[next[cells[i]]++ - first] = std::uint32_t(i - first);
}

template class NeighbourGrid<2>;
template class NeighbourGrid<3>;
} // namespace chipflex::sph
