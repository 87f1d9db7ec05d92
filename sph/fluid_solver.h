#pragma once
// FluidSolver<dim>: the weakly-compressible SPH fluid (2D per metre depth, or 3D).
//
// Life cycle
//   FluidSolver<2> fluid(parameters);             // FluidParameters: every option
//   fluid.add_fluid_particles(x, rho);            // set-up, any order
//   int id = fluid.add_wall(surface);             // WallSurface: LJ or dummy particles
//   fluid.add_hook(HookPoint::before_forces, f);  // optional per-step callbacks
//   while (fluid.time() < t_end) fluid.step();    // one adaptive time step
//
// Walls (the interface coupling/ uses; all vectors in world coordinates, SI):
//   add_wall(surface [, dummy positions])  returns the wall id. Lennard-Jones walls act
//       through their faces; dummy-particle walls get layers of boundary particles
//       (generated behind the faces, or the given positions), attached to the faces;
//       thin skins get them on the side of each face that needs them and keep the
//       fluid's sides apart (sph/thin_skins.h).
//   move_wall(id, vertices, velocities)    new vertex positions and velocities (call it
//       in a before_forces hook, i.e. for the state at time(), before the step).
//   wall_vertex_forces(id)                 after each step: the force of the fluid ON
//       every vertex (N; 2D: N per metre depth) from the force pass that determined
//       the step's velocity update (Verlet: the pass at the step start; symplectic:
//       the corrector pass at mid-step). Each particle-face contribution is split
//       with the barycentric weights of its foot point (LJ) or attachment (dummy), so
//       the sum over vertices is exactly minus what the fluid received: with the
//       symplectic scheme, sum(m v) changes by -dt * sum(vertex forces) (+ gravity).
//
// Step (one time step dt):
//   hooks(before_forces) -> sort by cell -> force pass (fluid, boundary, LJ walls,
//   gravity) -> dt = compute_time_step() -> hooks(after_forces) -> update -> t += dt ->
//   hooks(after_step). Symplectic adds a predictor half step and a second force pass.
// Time step: dt = min(CFL min(sqrt(h/|a|max), h/(c0 + h max(v.r/(r^2+eta2)))),
//   0.125 h^2/nu (laminar)).
//
// Determinism: every particle gathers its own sums in cell order; sorting is a stable,
// sequential counting sort; reductions are maxima. Results are bitwise independent of
// the thread count, and a checkpoint restores a run bitwise.
//
// Lost particles: a fluid particle that leaves the domain box, whose state turns
// non-finite or whose density leaves the density limits is removed at the next sort (the
// others keep their order, so a run with removals stays deterministic and restarts
// bitwise) and recorded in lost_particles(). One splash must not end a long run; many
// lost particles mean the case is wrong.
//
// Open boundaries (sph/open_boundary.h): add_open_boundary(zone) before the first step.
// Inlet and outlet buffers are fluid particles flagged with their zone; zones are
// handled outside the force loop: particles cross, are created and removed at the step
// start (transfer_open_boundaries), buffer states are prescribed or extrapolated after
// each sort (prescribe_open_boundaries), and their rates are zeroed after each pass so
// the integrators move them with their prescribed velocity. Outflow is counted per zone,
// apart from the lost particles (it does not count toward maximum_lost_fraction).
//
// MPI (sph/particle_exchange.h): distribute(exchange) before the first step spreads the
// fluid over the ranks in slabs; each rank then holds its own fluid particles and, as
// ghosts, the others' within reach (n_ghosts()); the walls stay whole on every rank. The
// time step is the global one. Not yet over MPI: open boundaries, thin skins, the
// position-Verlet scheme, checkpoints; bodies (their wall forces would need a sum).
//
// Failure: more than maximum_lost_fraction of the fluid lost, a boundary particle
// leaving the domain box, a non-finite acceleration or dt below minimum_time_step
// throws SimulationError naming the step, time and particle.

#include "sph/fluid_parameters.h"
#include "sph/open_boundary.h"
#include "sph/particle_arrays.h"
#include "sph/wall_surface.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace chipflex
{
class Hdf5File;
}

namespace chipflex::sph
{
template <int dim>
class ParticleExchange;
template <int dim>
struct HaloNeeds;

enum class ParticleKind
{
  boundary = 0,
  fluid = 1
};

/// Why a fluid particle was taken out of the run.
enum class LossCause
{
  left_domain, ///< outside the domain box
  non_finite,  ///< NaN or infinite position, velocity or density
  density      ///< density outside [minimum, maximum]_density_ratio * rho0
};

/// One removed fluid particle: when, which, where (its last position), why.
template <int dim>
struct LostParticle
{
  std::int64_t step = 0;
  double time = 0;
  std::uint32_t id = 0;
  Eigen::Matrix<double, dim, 1> position;
  LossCause cause = LossCause::left_domain;
  double density = 0; ///< its last density, kg/m^3

  /// "t = 0.245 s (step 1234): fluid particle 99 at (0.636, 0.384) left the domain box"
  std::string describe() const;
};

/// A record of the closest approach of two interacting fluid particles over a run: their
/// distance (m; infinity before the first check), when, and where (one of the two).
template <int dim>
struct ClosestPairRecord
{
  double distance = std::numeric_limits<double>::infinity();
  double time = 0;
  Eigen::Matrix<double, dim, 1> position = Eigen::Matrix<double, dim, 1>::Zero();

  bool seen() const { return distance < 1e300; }
};

enum class HookPoint
{
  before_forces, ///< state at time(); move walls here
  after_forces,  ///< forces and dt known (last_time_step()), state not yet advanced
  after_step     ///< state at the new time()
};

template <int dim>
class FluidSolver
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  using Hook = std::function<void(FluidSolver&)>;

  explicit FluidSolver(const FluidParameters<dim>& parameters);
  ~FluidSolver();
  FluidSolver(const FluidSolver&) = delete;
  FluidSolver& operator=(const FluidSolver&) = delete;

  // --- set-up (before the first step) -------------------------------------------------
  /// Fluid particles; densities empty: reference density; velocities empty: at rest.
  void add_fluid_particles(const std::vector<Vector>& positions,
                           const std::vector<double>& densities = {},
                           const std::vector<Vector>& velocities = {});
  /// Adds a wall; returns its id. `dummy_positions` (dummy model only): use these
  /// boundary particles (attached to the nearest faces) instead of generated layers;
  /// `dummy_densities`: their initial densities (default rho0).
  int add_wall(const WallSurface<dim>& wall, const std::vector<Vector>& dummy_positions = {},
               const std::vector<double>& dummy_densities = {});
  void add_hook(HookPoint point, Hook hook);
  /// An inlet or outlet buffer zone (sph/open_boundary.h). The fluid particles inside
  /// its box at set-up are its buffer: fill it with the fluid's lattice.
  void add_open_boundary(const OpenBoundary<dim>& zone);
  /// Spreads the fluid over MPI ranks (every rank builds the same case and calls this
  /// before the first step); see the header comment for what it covers.
  void distribute(std::shared_ptr<ParticleExchange<dim>> exchange);
  /// The rank layer, or null for a one-process run.
  const ParticleExchange<dim>* exchange() const { return exchange_.get(); }
  /// Ends the set-up: builds the particle arrays (boundary block first). Called by the
  /// first step(), save() or load(); call it yourself before reading particles of a
  /// solver that has not stepped yet. Idempotent.
  void initialise() { finish_setup(); }

  // --- stepping ---------------------------------------------------------------------------
  /// Advances one time step; returns dt.
  double step();
  double time() const { return time_; }
  std::int64_t step_count() const { return step_; }
  /// dt of the last (or current, from an after_forces hook) step.
  double last_time_step() const { return dt_; }
  /// dt from the forces of the last force pass (the rule above).
  double compute_time_step() const;

  // --- walls ------------------------------------------------------------------------------
  int n_walls() const { return int(walls_.size()); }
  const WallSurface<dim>& wall(int id) const { return walls_.at(id); }
  void move_wall(int id, const std::vector<Vector>& vertices,
                 const std::vector<Vector>& velocities);
  const std::vector<Vector>& wall_vertex_forces(int id) const { return vertex_forces_.at(id); }
  /// Some wall is a thin skin (WallModel::thin_skin, sph/thin_skins.h).
  bool has_thin_skins() const;
  /// Fluid particles the thin skins' guard has put back on their side so far (each
  /// one a particle that would have crossed a skin; none in a well-resolved run).
  std::size_t n_guarded() const;

  // --- particles (boundary block first: [0, n_boundary()), fluid after) ------------------
  std::size_t n_particles() const { return particles_.size(); }
  std::size_t n_boundary() const { return particles_.n_boundary; }
  std::size_t n_fluid() const { return particles_.n_fluid(); }
  /// Over MPI: the other ranks' fluid particles held here as ghosts (part of n_fluid()).
  std::size_t n_ghosts() const;
  const ParticleArrays<dim>& particles() const { return particles_; }
  /// Mutable access for hooks (e.g. an external body force added to the accelerations
  /// in an after_forces hook). Do not reorder or resize.
  ParticleArrays<dim>& particles() { return particles_; }
  ParticleKind kind(std::size_t i) const
  {
    return i < particles_.n_boundary ? ParticleKind::boundary : ParticleKind::fluid;
  }
  /// Unique over both kinds and kept for the whole run, restarts included: a boundary
  /// particle's id, then n_boundary + a fluid particle's id (ids follow the particles
  /// through every sort, and an inlet's new particle takes the next unused fluid id).
  std::uint64_t global_id(std::size_t i) const
  {
    const auto& p = particles_;
    return i < p.n_boundary ? std::uint64_t(p.id[i]) : std::uint64_t(p.n_boundary) + p.id[i];
  }
  /// The wall (add_wall's id) boundary particle i belongs to; -1 for a fluid particle.
  int wall_of(std::size_t i) const;
  Vector position(std::size_t i) const;
  Vector velocity(std::size_t i) const;
  double pressure(std::size_t i) const;
  /// The equation of state's (gauge) pressure at density rho.
  double pressure_at_density(double rho) const;
  /// Before the first step: removes the fluid particles for which `overlaps(x)` holds
  /// (e.g. inside a body placed in the water: GenCase-style filling removes them too);
  /// they never were part of the run. Returns how many.
  std::size_t remove_fluid_where(const std::function<bool(const Vector&)>& overlaps);
  /// Fluid particles removed so far, in the order of removal.
  const std::vector<LostParticle<dim>>& lost_particles() const { return lost_; }
  /// Fluid particles of the run so far: those it started with and those the inlets
  /// created (removed ones included).
  std::size_t n_fluid_created() const { return n_fluid_created_; }

  // --- open boundaries -------------------------------------------------------------------
  int n_open_boundaries() const { return int(zones_.size()); }
  const OpenBoundary<dim>& open_boundary(int k) const { return zones_.at(k); }
  /// Counts and the current mass flow through zone k (a scan of the particles).
  OpenBoundaryFlow open_boundary_flow(int k) const;
  /// Particles created by all inlets, and removed through all zones, so far.
  std::size_t n_inflow() const;
  std::size_t n_outflow() const;
  /// Particle i is a buffer particle of some zone.
  bool is_buffer(std::size_t i) const { return !particles_.zone.empty() && particles_.zone[i]; }
  /// Largest fluid speed seen at any force pass of the run so far, m/s, and when.
  double peak_fluid_speed() const { return peak_speed_; }
  double peak_fluid_speed_time() const { return peak_speed_time_; }
  /// Where the fastest particle was then (tells a method's squeeze from the flow's jet).
  const Vector& peak_fluid_speed_position() const { return peak_speed_position_; }
  /// Closest approach of two interacting fluid particles seen at any step so far, over
  /// the particles that are shifted (not in an open boundary's buffer, not beside a thin
  /// skin); particle shifting only (its sums measure it; not seen otherwise).
  const ClosestPairRecord<dim>& closest_fluid_pair() const { return closest_pair_; }
  /// The same over the fluid particles beside a thin skin (within its reach), which are
  /// not shifted (sph/fluid_solver_shifting.cc says why); particle shifting only.
  const ClosestPairRecord<dim>& closest_skin_side_pair() const { return closest_skin_pair_; }
  /// Under a background pressure: the peak so far of the share of the fluid particles in
  /// tension (absolute pressure, background included, below 0), a running mean over
  /// 100 h / c0; when it was; and the lowest absolute pressure of any fluid particle, Pa.
  /// Where a wake's suction exceeds the background pressure, the sum form of the pressure
  /// force pulls particles into pairs (the tensile instability); a flow whose background
  /// pressure covers its suction has none. Zero and +infinity without a background
  /// pressure.
  double tension_peak_fraction() const { return tension_peak_; }
  double tension_peak_time() const { return tension_peak_time_; }
  double lowest_absolute_pressure() const { return lowest_absolute_pressure_; }
  /// Every particle (fluid and boundary) has the mass rho0 dp^dim (2D: per metre).
  double particle_mass() const { return mass_; }
  double speed_of_sound() const { return parameters_.speed_of_sound; }
  const FluidParameters<dim>& parameters() const { return parameters_; }

  // --- restart and memory -------------------------------------------------------------
  /// Writes the complete state under `group` (particles bitwise, walls, time, step).
  void save(Hdf5File& file, const std::string& group) const { save(&file, group); }
  /// Over MPI every rank calls it (it gathers the fluid) and rank 0 writes: the others
  /// pass null. The file is the one-process one, so it restarts on any number of ranks.
  void save(Hdf5File* file, const std::string& group) const;
  /// Restores a state saved by save() for the same set-up (same walls, same counts).
  void load(const Hdf5File& file, const std::string& group);
  /// Bytes held by particle and neighbour-list arrays.
  std::size_t memory_bytes() const;

private:
  void finish_setup();
  void sort_and_bin();
  void force_pass();
  void update_verlet(double dt);
  void predict_symplectic(double dt);
  void correct_symplectic(double dt);
  void check_time_step(double dt) const;
  void remove_lost_particles();
  /// Stops the run (SimulationError) when more fluid than the case allows was lost.
  void check_lost_fraction() const;
  /// Over MPI, at each step's end: every rank's new losses, largest speed and closest
  /// pair to every rank, so that these records are the run's and the same on all ranks.
  void share_run_records();
  /// How far beyond its slab a rank needs the fluid (ParticleExchange::initialise).
  HaloNeeds<dim> exchange_halo_needs() const;
  /// Over MPI: the inlets' births and the zones' removals of this step summed over the
  /// ranks, and the first global id of this rank's births (the ranks number theirs in
  /// rank order). `created`, `removed`: this rank's counts per zone.
  std::size_t share_open_boundary_counts(std::size_t n_births,
                                         const std::vector<std::int64_t>& created,
                                         const std::vector<std::int64_t>& removed);
  /// Over MPI, after a force pass: each wall vertex's fluid force summed over the ranks
  /// (each rank holds its own particles' part), so that every rank's bodies and wall
  /// outputs see the whole fluid's load.
  void sum_vertex_forces_over_ranks();
  void transfer_open_boundaries();
  void prescribe_open_boundaries();
  void freeze_open_boundaries();
  void mirror_wall_velocities();
  void collect_walls_from_fluid();
  void extrapolate_wall_densities();
  /// Moves the fluid's density towards its kernel sum (FluidParameters::summation_blend).
  void sum_densities();
  void shift_particles(double dt);
  /// Under a background pressure: counts the fluid particles in tension after the
  /// pressures of a force pass (tension_peak_fraction()).
  void record_tension();
  /// Sides of the boundary particles [first, last) from their faces (thin skins).
  void update_dummy_sides(std::size_t first, std::size_t last);
  /// Sides of the fluid particles near thin skins, the guard (sph/thin_skins.h).
  void label_thin_skin_sides();
  float spray_fill_limit() const;
  /// The fluid particle with the largest acceleration of the last force pass.
  std::size_t most_accelerated_particle() const;
  void run_hooks(HookPoint point);
  [[noreturn]] void fail(std::size_t i, const std::string& problem) const;

  FluidParameters<dim> parameters_;
  double mass_, h_;
  ParticleArrays<dim> particles_;
  std::vector<WallSurface<dim>> walls_;
  std::vector<std::vector<Vector>> vertex_forces_;
  std::vector<std::pair<HookPoint, Hook>> hooks_;

  double time_ = 0, dt_ = 0;
  double force_time_ = 0; ///< the time of the state force_pass() evaluates (the frame's speed)
  std::int64_t step_ = 0;
  int verlet_counter_ = 0;
  bool forces_current_ = false; ///< accelerations and rates of the last pass are valid
  bool set_up_ = false, boundary_moved_ = true, walls_moved_ = true;
  float dot_rr2_max_ = 0;
  double acceleration_max_ = 0;
  std::vector<LostParticle<dim>> lost_;
  std::size_t lost_shared_ = 0; ///< over MPI: lost_[0, lost_shared_) is every rank's
  std::size_t n_fluid_created_ = 0, n_fluid_initial_ = 0;
  std::vector<OpenBoundary<dim>> zones_;
  std::vector<std::int64_t> zone_created_, zone_removed_;
  double peak_speed_ = 0, peak_speed_time_ = 0;
  Vector peak_speed_position_ = Vector::Zero();
  ClosestPairRecord<dim> closest_pair_, closest_skin_pair_;
  double tension_peak_ = 0, tension_peak_time_ = 0, tension_mean_ = 0, tension_mean_time_ = 0;
  double lowest_absolute_pressure_ = std::numeric_limits<double>::infinity();

  std::shared_ptr<ParticleExchange<dim>> exchange_;
  struct Impl;
  std::unique_ptr<Impl> impl_;
  // Staging before finish_setup().
  std::vector<Vector> staged_fluid_x_, staged_fluid_v_, staged_boundary_x_;
  std::vector<double> staged_fluid_rho_, staged_boundary_rho_;
};
} // namespace chipflex::sph
