#pragma once
// The particle state, structure of arrays. Boundary (dummy wall) particles come first,
// [0, n_boundary), fluid particles follow, [n_boundary, size()). Each block is kept
// sorted by neighbour cell so that a row of neighbour cells is one contiguous index
// range (see NeighbourGrid).
//
// Positions are double (a 1e-5 m step on a 1 m tank must not round away); velocities,
// densities and the force-pass results are float: the force arithmetic is float, as in
// DualSPHysics, which halves memory traffic and doubles the SIMD width.

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace chipflex::sph
{
/// Below these particle counts a loop runs on one thread: the OpenMP fork and barrier
/// cost more than the work, and on a loaded machine every barrier can stall for a
/// scheduler slice. The force loop is heavy (~0.3 us per particle per thread); the
/// light O(n) loops (update, cells, permutation: a few ns per particle) stay serial
/// up to 200k particles, so a step has one parallel region below that.
inline constexpr std::size_t parallel_threshold = 2000;
inline constexpr std::size_t light_parallel_threshold = 200000;
/// ParticleArrays::zone: the zone number k + 1 in the low bits, a flag in the top bit.
inline constexpr std::uint8_t zone_index_mask = 0x7f, zone_respawned = 0x80;

template <int dim>
struct ParticleArrays
{
  // State (saved in checkpoints, permuted by sorting).
  std::array<std::vector<double>, dim> position;
  std::array<std::vector<float>, dim> velocity;
  std::vector<float> density;
  /// Verlet: v and rho of the previous step; symplectic: of the step start.
  std::array<std::vector<float>, dim> velocity_previous;
  std::vector<float> density_previous;
  /// Symplectic only: positions at the step start.
  std::array<std::vector<double>, dim> position_previous;
  /// Stable particle number: boundary particles 0..n_boundary-1 (index of their wall
  /// attachment), fluid particles 0..n_fluid-1 (order of creation).
  std::vector<std::uint32_t> id;
  /// Filling of the kernel support at the last force pass (sph/force_loop.h); the next
  /// pass cuts the tension of particles below FluidSolver's spray threshold.
  std::vector<float> fill;
  /// Open boundaries only (empty otherwise): 0 for a fluid particle, k + 1 for a buffer
  /// particle of zone k (sph/open_boundary.h), plus zone_respawned for an inlet particle
  /// that has flowed back into its buffer (its replacement exists already).
  std::vector<std::uint8_t> zone;
  /// Thin skins only (empty otherwise; sph/thin_skins.h): the side of its nearest thin
  /// skin a particle is on, as a unit vector (from the skin's nearest point to a fluid
  /// particle; the normal of the face a dummy particle serves), and that skin's wall id
  /// + 1 (0: no thin skin within reach). A pair on opposite sides of one skin does not
  /// interact.
  std::array<std::vector<float>, dim> side;
  std::vector<float> skin;
  /// Runs over MPI only (empty otherwise; sph/particle_exchange.h): 0 for an owned
  /// particle that no other rank sees, k + 1 for an owned particle sent as the k-th ghost
  /// entry of this step, ghost_flag + j for a ghost (a copy of another rank's particle,
  /// the j-th received this step), whose state is refreshed before every force pass and
  /// whose own results are not used.
  std::vector<std::uint32_t> halo;

  // Results of the last force pass (not permuted: recomputed after every sort).
  std::array<std::vector<float>, dim> acceleration; ///< boundary: reaction force / mass
  std::vector<float> density_rate;
  std::vector<float> pressure_term; ///< p / rho^2
  std::vector<float> volume;        ///< m / rho
  std::vector<std::uint32_t> cell;

  std::size_t n_boundary = 0;
  std::size_t size() const { return density.size(); }
  std::size_t n_fluid() const { return size() - n_boundary; }

  static constexpr std::uint32_t ghost_flag = 0x80000000u;
  bool is_ghost(std::size_t i) const { return !halo.empty() && halo[i] >= ghost_flag; }

  void resize(std::size_t n, bool with_previous_positions, bool with_zones = false,
              bool with_sides = false, bool with_halo = false)
  {
    for (int d = 0; d < dim; ++d)
    {
      position[d].resize(n);
      velocity[d].resize(n);
      velocity_previous[d].resize(n);
      position_previous[d].resize(with_previous_positions ? n : 0);
      acceleration[d].resize(n);
      side[d].resize(with_sides ? n : 0);
    }
    skin.resize(with_sides ? n : 0);
    density.resize(n);
    density_previous.resize(n);
    id.resize(n);
    fill.resize(n, 1.0f);
    zone.resize(with_zones ? n : 0);
    halo.resize(with_halo ? n : 0);
    density_rate.resize(n);
    pressure_term.resize(n);
    volume.resize(n);
    cell.resize(n);
  }

  /// Applies new[k] = old[permutation[k]] over [first, first + permutation.size()) to
  /// every state array; `scratch` is reused between calls.
  void permute(std::size_t first, const std::vector<std::uint32_t>& permutation,
               std::vector<double>& scratch)
  {
    scratch.resize(permutation.size());
    for (int d = 0; d < dim; ++d)
    {
      apply(position[d], first, permutation, scratch);
      apply(velocity[d], first, permutation, scratch);
      apply(velocity_previous[d], first, permutation, scratch);
      if (!position_previous[d].empty())
        apply(position_previous[d], first, permutation, scratch);
      if (!side[d].empty())
        apply(side[d], first, permutation, scratch);
    }
    if (!skin.empty())
      apply(skin, first, permutation, scratch);
    apply(density, first, permutation, scratch);
    apply(density_previous, first, permutation, scratch);
    apply(id, first, permutation, scratch);
    apply(fill, first, permutation, scratch);
    if (!zone.empty())
      apply(zone, first, permutation, scratch);
    if (!halo.empty())
      apply(halo, first, permutation, scratch);
    apply(cell, first, permutation, scratch);
  }

  /// Appends one fluid particle at rest in every rate (an inlet's new buffer particle).
  void append(const double* x, const float* v, float rho, std::uint32_t new_id,
              std::uint8_t new_zone)
  {
    for (int d = 0; d < dim; ++d)
    {
      position[d].push_back(x[d]);
      velocity[d].push_back(v[d]);
      velocity_previous[d].push_back(v[d]);
      if (!position_previous[d].empty())
        position_previous[d].push_back(x[d]);
      acceleration[d].push_back(0.0f);
      if (!skin.empty())
        side[d].push_back(0.0f);
    }
    if (!skin.empty())
      skin.push_back(0.0f);
    density.push_back(rho);
    density_previous.push_back(rho);
    id.push_back(new_id);
    fill.push_back(1.0f);
    if (!zone.empty())
      zone.push_back(new_zone);
    if (!halo.empty())
      halo.push_back(0);
    density_rate.push_back(0.0f);
    pressure_term.push_back(0.0f);
    volume.push_back(0.0f);
    cell.push_back(0);
  }

  /// Removes the particles at `sorted_indices` (ascending, all >= n_boundary) from every
  /// array, keeping the order of the others: a removal is as deterministic as the run.
  void remove(const std::vector<std::size_t>& sorted_indices)
  {
    if (sorted_indices.empty())
      return;
    for (int d = 0; d < dim; ++d)
    {
      erase(position[d], sorted_indices);
      erase(velocity[d], sorted_indices);
      erase(velocity_previous[d], sorted_indices);
      erase(position_previous[d], sorted_indices);
      erase(acceleration[d], sorted_indices);
      erase(side[d], sorted_indices);
    }
    erase(skin, sorted_indices);
    erase(density, sorted_indices);
    erase(density_previous, sorted_indices);
    erase(id, sorted_indices);
    erase(fill, sorted_indices);
    erase(zone, sorted_indices);
    erase(halo, sorted_indices);
    erase(density_rate, sorted_indices);
    erase(pressure_term, sorted_indices);
    erase(volume, sorted_indices);
    erase(cell, sorted_indices);
  }

  std::size_t memory_bytes() const
  {
    std::size_t b = 0;
    for (int d = 0; d < dim; ++d)
      b += bytes(position[d]) + bytes(velocity[d]) + bytes(velocity_previous[d]) +
           bytes(position_previous[d]) + bytes(acceleration[d]) + bytes(side[d]);
    return b + bytes(density) + bytes(density_previous) + bytes(id) + bytes(fill) + bytes(zone) +
           bytes(halo) + bytes(skin) + bytes(density_rate) + bytes(pressure_term) + bytes(volume) +
           bytes(cell);
  }

private:
  template <typename T>
  static void erase(std::vector<T>& a, const std::vector<std::size_t>& sorted_indices)
  {
    if (a.empty()) // position_previous outside the symplectic schemes, sides, zones
      return;
    std::size_t out = sorted_indices.front(), next = 0;
    for (std::size_t i = out; i < a.size(); ++i)
    {
      if (next < sorted_indices.size() && sorted_indices[next] == i)
      {
        ++next;
        continue;
      }
      a[out++] = a[i];
    }
    a.resize(out);
  }
  template <typename T>
  static std::size_t bytes(const std::vector<T>& v)
  {
    return v.capacity() * sizeof(T);
  }
  template <typename T>
  static void apply(std::vector<T>& a, std::size_t first,
                    const std::vector<std::uint32_t>& permutation, std::vector<double>& scratch)
  {
    static_assert(sizeof(T) <= sizeof(double));
    const std::size_t n = permutation.size();
    if (n == 0) // an empty array's data() may be null, which memcpy must not get
      return;
    T* tmp = reinterpret_cast<T*>(scratch.data());
    T* base = a.data() + first;
#pragma omp parallel for schedule(static) if (n > light_parallel_threshold)
    for (std::size_t k = 0; k < n; ++k)
      tmp[k] = base[permutation[k]];
    std::memcpy(base, tmp, n * sizeof(T));
  }
};
} // namespace chipflex::sph
