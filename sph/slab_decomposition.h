#pragma once
// SlabDecomposition: the fluid cut into slabs along one axis, one slab per MPI rank.
//
// Rank r owns the particles with lower(r) <= x[axis] < upper(r); the outermost bounds are
// -inf and +inf, so every finite position has exactly one owner. A rank whose slab is
// empty (lower == upper: more ranks than cell layers, or no fluid there) owns nothing and
// receives nothing.
//
// Ghosts: a particle is copied to every other rank whose slab lies within the halo width
// of it. The width is at least two neighbour cells (4h): one cell for the fluid a rank's
// own particles see, and one more for the wall particles they see, whose densities are
// formed from the fluid around them (dynamic boundary particles). Values taken at mirror
// points (no-slip and sliding walls, open boundaries' buffers) widen it
// (FluidSolver::exchange_halo_width).
//
// The axis is the longest extent of the particles, fluid and walls, at the set-up.
// Cuts lie on the neighbour grid's cell layers and are chosen from a histogram of the
// fluid particles per layer, so that every rank gets about the same number
// (balanced_cuts). Slabs rather than recursive bisection: a drill flute, a channel or a
// tank is long in one direction, and a slab has two neighbours.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace chipflex::sph
{
/// A stretch [lower, upper] along the slab axis whose ranks need a wider halo: a rank
/// whose slab overlaps it gets at least `width` (an open boundary's buffer along the axis,
/// whose particles read the fluid at mirror points up to two buffer depths away).
struct WideHalo
{
  double lower, upper, width;
};

class SlabDecomposition
{
public:
  SlabDecomposition() = default;
  /// `cuts`: the n_ranks - 1 inner bounds, ascending (equal cuts make empty slabs).
  /// `halo_width` for every rank, wider where `wide` says.
  SlabDecomposition(int axis, const std::vector<double>& cuts, double halo_width,
                    const std::vector<WideHalo>& wide = {})
      : axis_(axis), halo_(halo_width), wide_(wide)
  {
    bounds_.clear();
    bounds_.push_back(-std::numeric_limits<double>::infinity());
    for (std::size_t k = 0; k < cuts.size(); ++k)
    {
      if (k > 0 && !(cuts[k] >= cuts[k - 1]))
        throw std::invalid_argument("SlabDecomposition: the cuts must ascend");
      bounds_.push_back(cuts[k]);
    }
    bounds_.push_back(std::numeric_limits<double>::infinity());
    halos_.assign(n_ranks(), halo_width);
    for (int r = 0; r < n_ranks(); ++r)
      for (const auto& w : wide_)
        if (!empty(r) && upper(r) >= w.lower && lower(r) <= w.upper)
          halos_[r] = std::max(halos_[r], w.width);
  }

  int n_ranks() const { return int(bounds_.size()) - 1; }
  int axis() const { return axis_; }
  /// The halo width of every rank, and of one rank (wider where a WideHalo lies).
  double halo_width() const { return halo_; }
  double halo_width(int rank) const { return halos_[rank]; }
  const std::vector<WideHalo>& wide_halos() const { return wide_; }
  double lower(int rank) const { return bounds_[rank]; }
  double upper(int rank) const { return bounds_[rank + 1]; }
  bool empty(int rank) const { return !(lower(rank) < upper(rank)); }

  /// The rank that owns a point; -1 for a NaN coordinate (the particle stays where it is
  /// and is removed as lost by its rank).
  int owner(const double* x) const
  {
    const double s = x[axis_];
    if (std::isnan(s))
      return -1;
    return owner_of_coordinate(s);
  }

  /// Calls f(rank) for every rank other than `owner` with a non-empty slab within its
  /// halo width of the point, in ascending rank order.
  template <class F>
  void for_each_ghost_rank(const double* x, int owner, F&& f) const
  {
    const double s = x[axis_];
    for (int r = 0; r < n_ranks(); ++r)
      if (r != owner && !empty(r) && s >= lower(r) - halos_[r] && s < upper(r) + halos_[r])
        f(r);
  }

  /// Inner cuts for n_ranks slabs from the work in each cell layer (layer k spans
  /// [origin + k w, origin + (k + 1) w)): cut r lies at the first layer boundary with at
  /// least r / n_ranks of the work below it.
  static std::vector<double> balanced_cuts(const std::vector<double>& per_layer, double origin,
                                           double layer_width, int n_ranks)
  {
    double total = 0;
    for (const auto c : per_layer)
      total += c;
    std::vector<double> cuts;
    double below = 0;
    std::size_t k = 0;
    for (int r = 1; r < n_ranks; ++r)
    {
      // below >= r total / n_ranks, in integers.
      while (k < per_layer.size() && below * n_ranks < r * total)
        below += per_layer[k++];
      cuts.push_back(origin + double(k) * layer_width);
    }
    return cuts;
  }

  /// The work each rank would get with these cuts, from the same histogram.
  std::vector<double> loads(const std::vector<double>& per_layer, double origin,
                            double layer_width) const
  {
    std::vector<double> load(n_ranks(), 0.0);
    for (std::size_t k = 0; k < per_layer.size(); ++k)
    {
      const double centre = origin + (double(k) + 0.5) * layer_width;
      load[owner_of_coordinate(centre)] += per_layer[k];
    }
    return load;
  }

private:
  /// The slab holding s: the last bound at or below it (upper_bound over the inner bounds).
  int owner_of_coordinate(double s) const
  {
    return int(std::upper_bound(bounds_.begin() + 1, bounds_.end() - 1, s) - bounds_.begin()) - 1;
  }

  int axis_ = 0;
  double halo_ = 0;
  std::vector<WideHalo> wide_;
  std::vector<double> halos_{0.0};
  std::vector<double> bounds_{-std::numeric_limits<double>::infinity(),
                              std::numeric_limits<double>::infinity()};
};
} // namespace chipflex::sph
