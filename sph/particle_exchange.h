#pragma once
// ParticleExchange<dim>: the fluid spread over MPI ranks (sph/slab_decomposition.h).
//
// Every rank builds the whole case (the set-up is cheap next to the run) and then keeps
// the fluid particles of its own slab; the wall (boundary) particles stay on every rank.
// Each step:
//   exchange()        at the step start: drops last step's ghosts, sends the particles
//                     that left the slab to their new owner (migration), rebalances the
//                     cuts now and then, and receives as ghosts the other ranks'
//                     particles within the halo width of the slab;
//   refresh_ghosts()  before a later force pass of the same step (the symplectic
//                     corrector), and after the open boundaries set their buffers: the
//                     owners send the ghosts' new states;
//   maximum()         the time step's maxima over all ranks.
// A ghost is a fluid particle flagged in ParticleArrays::halo: it takes part in the force
// pass as a neighbour, and its own sums are skipped (as are those of the wall particles
// beyond a cell of the slab, whose densities go stale until synchronised when the cuts
// move).
//
// Determinism: each rank's arrays, and so its answers, depend only on the number of
// ranks; runs on different numbers of ranks sum the same pairs in another order and agree
// to rounding, which a dam break's splash then amplifies (docs/parallel.md).
//
// mpi.h stays in the .cc: the communicator is MPI_COMM_WORLD.

#include "sph/particle_arrays.h"
#include "sph/slab_decomposition.h"

#include <Eigen/Core>
#include <cstdint>
#include <utility>
#include <vector>

namespace chipflex::sph
{
/// Whether this process was started by mpirun (or srun) with more than one rank; read
/// from the launcher's environment, so it works before MPI_Init.
bool launched_on_several_ranks();

/// MPI_Init_thread (funneled: only the thread that steps calls MPI) unless MPI is up
/// already; MPI_Finalize at exit if this object started it and its scope was not left by
/// an exception.
class MpiSession
{
public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int n_ranks() const { return n_ranks_; }

private:
  int rank_ = 0, n_ranks_ = 1;
};

/// Time spent in the exchange and its traffic, accumulated over the run (this rank).
struct ExchangeStatistics
{
  double migration_seconds = 0; ///< sending the particles that changed rank
  double halo_seconds = 0;      ///< building and refreshing the ghosts
  double reduction_seconds = 0; ///< the time step's global maxima
  std::uint64_t migrated = 0;   ///< particles received from other ranks
  std::uint64_t ghosts = 0;     ///< ghosts received, summed over the steps
  std::uint64_t rebalances = 0; ///< times the cuts moved
};

/// How wide a halo a case needs (FluidSolver::exchange_halo_needs), for each axis the
/// slabs may be cut along: `width[axis]` everywhere, wider on the stretches in `wide`
/// that lie along that axis.
template <int dim>
struct HaloNeeds
{
  Eigen::Matrix<double, dim, 1> width;
  std::vector<std::pair<int, WideHalo>> wide; ///< (axis, stretch)
};

template <int dim>
class ParticleExchange
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;

  /// Needs MPI to be initialised (MpiSession).
  ParticleExchange();

  int rank() const { return rank_; }
  int n_ranks() const { return n_ranks_; }
  const SlabDecomposition& decomposition() const { return slabs_; }
  const ExchangeStatistics& statistics() const { return statistics_; }

  /// Set-up: `p` holds every fluid particle of the case on every rank. Cuts the slabs
  /// along the particles' longest extent (fluid and walls), on the neighbour grid's layers
  /// of width `cell_size` over the domain box, and keeps this rank's own fluid particles.
  /// A restart calls it again with the checkpoint's particles (on any number of ranks).
  /// `halo`: how far beyond its slab a rank needs the fluid, at least two cells
  /// (sph/slab_decomposition.h); more where values are taken at mirror points.
  void initialise(ParticleArrays<dim>& p, const Vector& domain_min, const Vector& domain_max,
                  double cell_size, const HaloNeeds<dim>& halo);
  /// Step start: ghosts out, migration, rebalancing (every `rebalance_every` calls, when
  /// the busiest rank holds more than 5 % above the mean), ghosts in.
  void exchange(ParticleArrays<dim>& p);
  /// The owners' current states into this step's ghosts. A ghost whose owner has lost
  /// the particle since gets NaN, to be dropped at the next sort; with `keep_lost` (after
  /// the sort) it keeps its state instead, for the rest of this pass.
  void refresh_ghosts(ParticleArrays<dim>& p, bool keep_lost = false);
  /// In place: each value becomes its maximum over the ranks.
  void maximum(double* values, int n);
  /// In place: each value becomes its sum over the ranks.
  void sum(double* values, int n) const;
  /// Every rank's `mine`, concatenated in rank order, on every rank.
  std::vector<double> all_gather(const std::vector<double>& mine) const;
  /// Outputs and checkpoints: on rank 0, the whole fluid in one set of arrays (rank 0's
  /// wall block, with each wall particle's density and velocity from the rank that computes them,
  /// then every rank's own fluid particles in rank order, no ghosts); empty on the others.
  ParticleArrays<dim> gather(const ParticleArrays<dim>& p) const;
  /// Outputs written by every rank together (parallel HDF5): this rank's share of the
  /// whole fluid, no ghosts: on rank 0 the wall block (states as in gather) and its own
  /// fluid particles, on the others their own fluid particles (n_boundary 0). Collective.
  ParticleArrays<dim> own_rows(const ParticleArrays<dim>& p) const;
  std::size_t n_ghosts() const { return n_ghosts_; }

  int rebalance_every = 100;
  /// A wall particle's work against a fluid particle's in the balance.
  double wall_weight = 0.25;

private:
  /// Particles per cell layer along the axis, summed over the ranks: the work to share.
  /// A wall particle costs about what a fluid particle does (its sums run over the fluid
  /// only, but it has fewer neighbours), so both count.
  std::vector<double> global_histogram(const ParticleArrays<dim>& p) const;
  void add_to_histogram(const ParticleArrays<dim>& p, int axis, std::size_t first, std::size_t last,
                        double weight, std::vector<double>& per_layer) const;
  void rebalance(const ParticleArrays<dim>& p);
  /// The rank that owns particle i's position (-1: NaN).
  int owner_of(const ParticleArrays<dim>& p, std::size_t i) const;
  void migrate(ParticleArrays<dim>& p);
  /// After the cuts moved: a rank computes only the wall particles within a cell of its
  /// slab (the others' densities go stale), so every wall particle's density is taken
  /// from the rank that owned its position under the `old` cuts.
  void synchronise_walls(ParticleArrays<dim>& p, const SlabDecomposition& old);
  /// Each wall particle's density, previous density, density rate and velocity from the
  /// rank that owns its position under `slabs`: on every rank (`everywhere`) or on rank 0
  /// only.
  std::vector<double> wall_states(const ParticleArrays<dim>& p, const SlabDecomposition& slabs,
                                  bool everywhere) const;
  static void set_wall_states(const std::vector<double>& values, ParticleArrays<dim>& p);
  void build_ghosts(ParticleArrays<dim>& p);
  /// Sends send[r] to rank r and returns what every rank sent here, in rank order.
  std::vector<double> all_to_all(const std::vector<std::vector<double>>& send,
                                 std::vector<int>* received_counts = nullptr) const;

  int rank_ = 0, n_ranks_ = 1;
  SlabDecomposition slabs_;
  double origin_ = 0, layer_width_ = 1;
  std::size_t n_layers_ = 1;
  std::uint64_t calls_ = 0, old_rebalances_ = 0;
  /// This step's ghost entries: owned entry k went to rank entry_rank_[...] at record
  /// slot entry_slot_[...], over [entry_first_[k], entry_first_[k + 1]).
  std::vector<std::uint32_t> entry_first_;
  std::vector<int> entry_rank_;
  std::vector<std::uint32_t> entry_slot_;
  std::vector<int> send_counts_; ///< ghost records per destination rank
  std::size_t n_ghosts_ = 0;
  /// Whether the records carry the zone flags and thin-skin sides (the case has them).
  bool tags_ = false;
  ExchangeStatistics statistics_;
};
} // namespace chipflex::sph
