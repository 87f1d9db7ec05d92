// FluidSolver: set-up, the step sequence, time integration and walls. The force pass
// itself is in fluid_solver_forces.cc, checkpoints in fluid_solver_checkpoint.cc.

#include "sph/fluid_solver.h"

#include "common/input_error.h"
#include "sph/dummy_wall_particles.h"
#include "sph/fluid_solver_impl.h"
#include "sph/particle_exchange.h"
#include "sph/thin_skins.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace chipflex::sph
{
template <int dim>
FluidSolver<dim>::FluidSolver(const FluidParameters<dim>& parameters)
    : parameters_(parameters), mass_(parameters.particle_mass()), h_(parameters.smoothing_length()),
      impl_(std::make_unique<Impl>())
{
  const auto& p = parameters_;
  if (!(p.particle_spacing > 0) || !(p.reference_density > 0) || !(p.speed_of_sound > 0) ||
      !(p.smoothing_coefficient > 0) || !(p.cfl > 0) || !(p.gamma >= 1))
    throw InputError("fluid", "particle spacing, density, speed of sound, smoothing "
                              "coefficient, CFL must be positive and gamma >= 1");
  if (p.verlet_euler_every < 1)
    throw InputError("time/verlet euler every", "must be at least 1");
}

template <int dim>
FluidSolver<dim>::~FluidSolver() = default;

template <int dim>
void FluidSolver<dim>::add_fluid_particles(const std::vector<Vector>& x,
                                           const std::vector<double>& rho,
                                           const std::vector<Vector>& v)
{
  if (set_up_)
    throw std::logic_error("FluidSolver: particles can only be added before the first step");
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    staged_fluid_x_.push_back(x[i]);
    staged_fluid_rho_.push_back(rho.empty() ? parameters_.reference_density : rho.at(i));
    staged_fluid_v_.push_back(v.empty() ? Vector::Zero() : v.at(i));
  }
}

template <int dim>
int FluidSolver<dim>::add_wall(const WallSurface<dim>& wall,
                               const std::vector<Vector>& dummy_positions,
                               const std::vector<double>& dummy_densities)
{
  if (set_up_)
    throw std::logic_error("FluidSolver: walls can only be added before the first step");
  WallSurface<dim> w = wall;
  if (w.velocities.empty())
    w.velocities.assign(w.vertices.size(), Vector::Zero());
  if (w.velocities.size() != w.vertices.size())
    throw InputError("wall " + w.name, "needs one velocity per vertex");
  for (const auto& f : w.faces)
    for (int k = 0; k < dim; ++k)
      if (f[k] < 0 || std::size_t(f[k]) >= w.vertices.size())
        throw InputError("wall " + w.name, "a face refers to a missing vertex");
  const std::uint32_t id = std::uint32_t(walls_.size());
  const double dp = parameters_.particle_spacing;
  if (w.model == WallModel::lennard_jones)
    w.lennard_jones = derive_lennard_jones(
        w.lennard_jones, dp, parameters_.reference_density,
        parameters_.reference_density * std::pow(0.1 * parameters_.speed_of_sound, 2), w.name);
  else if (w.model == WallModel::thin_skin && !w.fluid_passes)
  {
    const int layers = w.dummy_layers > 0 ? w.dummy_layers : int(std::ceil(2 * h_ / dp));
    std::vector<WallAttachment<dim>> attachments;
    if (dummy_positions.empty())
      attachments = generate_thin_skin_dummies(w, id, dp, layers);
    else
      for (const Vector& x : dummy_positions)
        attachments.push_back(attach_to_wall(w, id, x));
    if (!dummy_densities.empty() && dummy_densities.size() != attachments.size())
      throw std::invalid_argument("FluidSolver::add_wall: one density per dummy particle");
    for (std::size_t k = 0; k < attachments.size(); ++k)
    {
      Vector x, v;
      attached_state(w, attachments[k], x, v);
      staged_boundary_x_.push_back(x);
      staged_boundary_rho_.push_back(dummy_densities.empty() ? parameters_.reference_density
                                                             : dummy_densities[k]);
      impl_->attachments.push_back(attachments[k]);
    }
  }
  else if (!w.fluid_passes)
  {
    const int layers = w.dummy_layers > 0 ? w.dummy_layers : int(std::ceil(2 * h_ / dp));
    const auto points =
        dummy_positions.empty() ? generate_dummy_particles(w, dp, layers) : dummy_positions;
    if (!dummy_densities.empty() && dummy_densities.size() != points.size())
      throw std::invalid_argument("FluidSolver::add_wall: one density per dummy particle");
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      const Vector& x = points[k];
      staged_boundary_x_.push_back(x);
      staged_boundary_rho_.push_back(dummy_densities.empty() ? parameters_.reference_density
                                                             : dummy_densities[k]);
      impl_->attachments.push_back(attach_to_wall(w, id, x));
    }
  }
  impl_->wall_closed.push_back(w.model == WallModel::thin_skin && is_closed(w));
  walls_.push_back(std::move(w));
  vertex_forces_.emplace_back(walls_.back().vertices.size(), Vector::Zero());
  impl_->guard_forces.emplace_back(walls_.back().vertices.size(), Vector::Zero());
  return int(id);
}

template <int dim>
bool FluidSolver<dim>::has_thin_skins() const
{
  for (const auto& w : walls_)
    if (w.model == WallModel::thin_skin && !w.fluid_passes)
      return true;
  return false;
}

template <int dim>
std::size_t FluidSolver<dim>::n_guarded() const
{
  return impl_->n_guarded;
}

template <int dim>
void FluidSolver<dim>::update_dummy_sides(std::size_t first, std::size_t last)
{
  auto& p = particles_;
  if (p.skin.empty())
    return;
  for (std::size_t i = first; i < last; ++i)
  {
    const auto& a = impl_->attachments[p.id[i]];
    float side[dim] = {}, skin = 0;
    if (a.wall != WallAttachment<dim>::no_wall && walls_[a.wall].model == WallModel::thin_skin)
      dummy_side(walls_[a.wall], a, side, skin);
    for (int d = 0; d < dim; ++d)
      p.side[d][i] = side[d];
    p.skin[i] = skin;
  }
}

template <int dim>
void FluidSolver<dim>::add_hook(HookPoint point, Hook hook)
{
  hooks_.emplace_back(point, std::move(hook));
}

template <int dim>
void FluidSolver<dim>::run_hooks(HookPoint point)
{
  for (auto& [p, hook] : hooks_)
    if (p == point)
      hook(*this);
}

template <int dim>
void FluidSolver<dim>::finish_setup()
{
  if (set_up_)
    return;
  set_up_ = true;
  auto& p = particles_;
  const std::size_t nb = staged_boundary_x_.size(), nf = staged_fluid_x_.size();
  p.n_boundary = nb;
  n_fluid_created_ = n_fluid_initial_ = nf;
  p.resize(nb + nf, is_symplectic(parameters_.scheme), !zones_.empty(), has_thin_skins());
  for (std::size_t i = 0; i < nb + nf; ++i)
  {
    const bool fluid = i >= nb;
    const Vector& x = fluid ? staged_fluid_x_[i - nb] : staged_boundary_x_[i];
    const Vector v = fluid ? staged_fluid_v_[i - nb] : Vector::Zero();
    const float rho = float(fluid ? staged_fluid_rho_[i - nb] : staged_boundary_rho_[i]);
    for (int d = 0; d < dim; ++d)
    {
      p.position[d][i] = x[d];
      if (!p.position_previous[d].empty())
        p.position_previous[d][i] = x[d];
      p.velocity[d][i] = p.velocity_previous[d][i] = float(v[d]);
    }
    p.density[i] = p.density_previous[i] = rho;
    p.id[i] = std::uint32_t(fluid ? i - nb : i);
    // The fluid's lattice inside a zone's box is that zone's buffer.
    for (std::size_t k = 0; fluid && k < zones_.size(); ++k)
    {
      const double depth = zones_[k].depth(x.data());
      if (zones_[k].in_section(x.data()) && depth > 0 && depth <= zones_[k].thickness())
      {
        p.zone[i] = std::uint8_t(k + 1);
        break;
      }
    }
  }
  for (std::size_t i = 0; i < nb; ++i)
  {
    const auto& a = impl_->attachments[i];
    if (a.wall != WallAttachment<dim>::no_wall)
    {
      Vector x, v;
      attached_state(walls_[a.wall], a, x, v);
      for (int d = 0; d < dim; ++d)
        p.velocity[d][i] = p.velocity_previous[d][i] = float(v[d]);
    }
  }
  update_dummy_sides(0, nb);
  staged_fluid_x_ = {};
  staged_fluid_v_ = {};
  staged_boundary_x_ = {};
  staged_fluid_rho_ = {};
  staged_boundary_rho_ = {};
  impl_->setup(parameters_, has_thin_skins());
  if (exchange_)
  {
    exchange_->initialise(p, parameters_.domain_min, parameters_.domain_max,
                          impl_->grid.cell_size(), exchange_halo_needs());
  }
}

template <int dim>
void FluidSolver<dim>::distribute(std::shared_ptr<ParticleExchange<dim>> exchange)
{
  if (set_up_)
    throw std::logic_error("FluidSolver::distribute after the set-up");
  exchange_ = std::move(exchange);
}

template <int dim>
std::size_t FluidSolver<dim>::n_ghosts() const
{
  std::size_t n = 0;
  for (std::size_t i = particles_.n_boundary; i < particles_.size(); ++i)
    n += particles_.is_ghost(i);
  return n;
}

template <int dim>
void FluidSolver<dim>::move_wall(int id, const std::vector<Vector>& vertices,
                                 const std::vector<Vector>& velocities)
{
  auto& w = walls_.at(id);
  if (vertices.size() != w.vertices.size() || velocities.size() != w.vertices.size())
    throw std::invalid_argument("FluidSolver::move_wall: wall '" + w.name + "' has " +
                                std::to_string(w.vertices.size()) + " vertices");
  w.vertices = vertices;
  w.velocities = velocities;
  walls_moved_ = true;
  if (w.model == WallModel::lennard_jones || !set_up_)
    return;
  auto& p = particles_;
  const bool sided = w.model == WallModel::thin_skin && !p.skin.empty();
  for (std::size_t i = 0; i < p.n_boundary; ++i)
  {
    const auto& a = impl_->attachments[p.id[i]];
    if (a.wall != std::uint32_t(id))
      continue;
    Vector x, v;
    attached_state(w, a, x, v);
    for (int d = 0; d < dim; ++d)
    {
      p.position[d][i] = x[d];
      p.velocity[d][i] = float(v[d]);
    }
    if (sided)
      update_dummy_sides(i, i + 1);
  }
  boundary_moved_ = true;
}

template <int dim>
int FluidSolver<dim>::wall_of(std::size_t i) const
{
  if (i >= particles_.n_boundary)
    return -1;
  const auto wall = impl_->attachments[particles_.id[i]].wall;
  return wall == WallAttachment<dim>::no_wall ? -1 : int(wall);
}

template <int dim>
typename FluidSolver<dim>::Vector FluidSolver<dim>::position(std::size_t i) const
{
  Vector x;
  for (int d = 0; d < dim; ++d)
    x[d] = particles_.position[d][i];
  return x;
}

template <int dim>
typename FluidSolver<dim>::Vector FluidSolver<dim>::velocity(std::size_t i) const
{
  Vector v;
  for (int d = 0; d < dim; ++d)
    v[d] = particles_.velocity[d][i];
  return v;
}

template <int dim>
double FluidSolver<dim>::pressure(std::size_t i) const
{
  return impl_->eos.pressure(double(particles_.density[i]));
}

template <int dim>
double FluidSolver<dim>::pressure_at_density(double rho) const
{
  return impl_->eos.pressure(rho);
}

template <int dim>
void FluidSolver<dim>::fail(std::size_t i, const std::string& problem) const
{
  std::ostringstream s;
  s.precision(6);
  s << "step " << step_ << ", t = " << time_
    << " s: " << (kind(i) == ParticleKind::fluid ? "fluid" : "boundary") << " particle "
    << particles_.id[i] << " at (";
  for (int d = 0; d < dim; ++d)
    s << (d ? ", " : "") << particles_.position[d][i];
  s << ") " << problem;
  throw SimulationError(s.str());
}

template <int dim>
double FluidSolver<dim>::compute_time_step() const
{
  const auto& p = parameters_;
  const double dt_force = acceleration_max_ > 0 ? std::sqrt(h_ / acceleration_max_) : 1e30;
  const double dt_cv = h_ / (p.speed_of_sound + h_ * std::max(0.0, double(dot_rr2_max_)));
  double dt = p.cfl * std::min(dt_force, dt_cv);
  if (p.viscosity == ViscosityModel::laminar && p.kinematic_viscosity > 0)
    dt = std::min(dt, 0.125 * h_ * h_ / p.kinematic_viscosity);
  return dt;
}

template <int dim>
void FluidSolver<dim>::check_time_step(double dt) const
{
  if (!(dt >= parameters_.minimum_time_step))
  {
    std::ostringstream s;
    s << "the time step collapsed to " << dt << " s (minimum " << parameters_.minimum_time_step
      << " s; largest acceleration " << acceleration_max_ << " m/s^2)";
    fail(most_accelerated_particle(), s.str());
  }
}

template <int dim>
std::string LostParticle<dim>::describe() const
{
  std::ostringstream s;
  s.precision(6);
  s << "t = " << time << " s (step " << step << "): fluid particle " << id << " at (";
  for (int d = 0; d < dim; ++d)
    s << (d ? ", " : "") << position[d];
  s << ") ";
  if (cause == LossCause::left_domain)
    s << "left the domain box";
  else if (cause == LossCause::non_finite)
    s << "has a non-finite position, velocity or density";
  else
    s << "has the density " << density << " kg/m^3, outside the density limits";
  return s.str();
}

template <int dim>
std::size_t FluidSolver<dim>::remove_fluid_where(const std::function<bool(const Vector&)>& overlaps)
{
  if (set_up_)
    throw std::logic_error("FluidSolver::remove_fluid_where after the first step");
  // The particles are still staged (finish_setup() builds the arrays at the first step).
  std::size_t kept = 0;
  for (std::size_t i = 0; i < staged_fluid_x_.size(); ++i)
    if (!overlaps(staged_fluid_x_[i]))
    {
      staged_fluid_x_[kept] = staged_fluid_x_[i];
      staged_fluid_rho_[kept] = staged_fluid_rho_[i];
      staged_fluid_v_[kept] = staged_fluid_v_[i];
      ++kept;
    }
  const std::size_t removed = staged_fluid_x_.size() - kept;
  staged_fluid_x_.resize(kept);
  staged_fluid_rho_.resize(kept);
  staged_fluid_v_.resize(kept);
  return removed;
}

template <int dim>
void FluidSolver<dim>::remove_lost_particles()
{
  auto& p = particles_;
  const std::size_t nb = p.n_boundary;
  std::vector<std::size_t> gone;
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    bool finite = std::isfinite(p.density[i]);
    for (int d = 0; d < dim; ++d)
      finite = finite && std::isfinite(p.velocity[d][i]) && std::isfinite(p.position[d][i]);
    const bool outside = p.cell[i] == NeighbourGrid<dim>::outside;
    const double rho0 = parameters_.reference_density;
    const bool density_ok = i < nb || (p.density[i] >= parameters_.minimum_density_ratio * rho0 &&
                                       p.density[i] <= parameters_.maximum_density_ratio * rho0);
    if (finite && !outside && density_ok)
      continue;
    if (p.is_ghost(i)) // its owner has the particle, and counts it if it is lost
    {
      gone.push_back(i);
      continue;
    }
    if (i < nb) // a wall particle: the walls' motion is wrong, not one splash
      fail(i, finite ? "left the domain box" : "has a non-finite state (the run blew up)");
    LostParticle<dim> lost;
    lost.step = step_;
    lost.time = time_;
    lost.id = p.id[i];
    for (int d = 0; d < dim; ++d)
      lost.position[d] = p.position[d][i];
    lost.cause = !finite   ? LossCause::non_finite
                 : outside ? LossCause::left_domain
                           : LossCause::density;
    lost.density = p.density[i];
    lost_.push_back(lost);
    gone.push_back(i);
  }
  p.remove(gone);
  // Over MPI the other ranks' losses count too: checked once they are shared.
  if (!exchange_)
    check_lost_fraction();
}

template <int dim>
void FluidSolver<dim>::check_lost_fraction() const
{
  const double fraction = double(lost_.size()) / double(std::max<std::size_t>(1, n_fluid_created_));
  if (fraction > parameters_.maximum_lost_fraction)
  {
    std::ostringstream s;
    s.precision(4);
    s << lost_.size() << " of " << n_fluid_created_ << " fluid particles lost (" << 100 * fraction
      << " %, more than the limit of " << 100 * parameters_.maximum_lost_fraction
      << " %); the last: " << lost_.back().describe();
    throw SimulationError(s.str());
  }
}

template <int dim>
std::size_t FluidSolver<dim>::most_accelerated_particle() const
{
  const auto& p = particles_;
  std::size_t best = p.n_boundary;
  double best_a2 = -1;
  for (std::size_t i = p.n_boundary; i < p.size(); ++i)
  {
    double a2 = 0;
    for (int d = 0; d < dim; ++d)
      a2 += double(p.acceleration[d][i]) * double(p.acceleration[d][i]);
    if (a2 > best_a2)
      best = i, best_a2 = a2;
  }
  return best;
}

template <int dim>
double FluidSolver<dim>::step()
{
  finish_setup();
  // The guard's put-backs of the whole step load the skins (sph/thin_skins.h).
  for (auto& forces : impl_->guard_forces)
    for (auto& f : forces)
      f.setZero();
  run_hooks(HookPoint::before_forces);
  if (!zones_.empty())
    transfer_open_boundaries();
  if (exchange_)
    exchange_->exchange(particles_);
  // position_verlet reuses the previous step's mid-step pass for the predictor (and dt);
  // only the first step (no pass yet) evaluates the forces at t_n.
  if (parameters_.scheme != TimeScheme::position_verlet || !forces_current_)
  {
    force_time_ = time_;
    force_pass();
  }
  forces_current_ = true;
  const double dt = compute_time_step();
  check_time_step(dt);
  dt_ = dt;
  run_hooks(HookPoint::after_forces);
  if (parameters_.scheme == TimeScheme::verlet)
    update_verlet(dt);
  else
  {
    predict_symplectic(dt);
    force_time_ = time_ + 0.5 * dt; // the mid-step state
    if (exchange_)
      exchange_->refresh_ghosts(particles_);
    force_pass();
    correct_symplectic(dt);
  }
  if (parameters_.shifting_coefficient > 0)
    shift_particles(dt);
  time_ += dt;
  ++step_;
  if (exchange_)
  {
    share_run_records();
    check_lost_fraction();
  }
  run_hooks(HookPoint::after_step);
  return dt;
}

// Spray is water at the surrounding (zero) pressure: a fluid particle whose kernel support
// is less than spray_fill_threshold filled keeps rho >= rho0, as a wall particle does, so
// it holds no tension. Without that, a detached pair below rho0 attracts, binds, orbits
// with its density drifting down and flies apart at several times c0 (docs/sph.md).
template <int dim>
float FluidSolver<dim>::spray_fill_limit() const
{
  return parameters_.cut_spray_tension ? float(spray_fill_threshold) : 0.0f;
}

template <int dim>
void FluidSolver<dim>::update_verlet(double dt)
{
  auto& p = particles_;
  const std::size_t nb = p.n_boundary, n = p.size();
  const bool euler = ++verlet_counter_ >= parameters_.verlet_euler_every;
  if (euler)
    verlet_counter_ = 0;
  // Leapfrog over two steps from the previous state; every few steps an Euler step
  // from the current state decouples the odd and even step sequences (DualSPHysics).
  const float dtv = float(euler ? dt : 2 * dt);
  const float rho0 = float(parameters_.reference_density);
  const float spray_fill = spray_fill_limit();
#pragma omp parallel for schedule(static) if (n > light_parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
  {
    const float base_rho = euler ? p.density[i] : p.density_previous[i];
    float rho = base_rho + dtv * p.density_rate[i];
    p.density_previous[i] = p.density[i];
    if (i < nb)
    {
      p.density[i] = std::max(rho, rho0); // DBC: a wall never pulls the fluid
      continue;
    }
    p.density[i] = p.fill[i] < spray_fill ? std::max(rho, rho0) : rho;
    for (int d = 0; d < dim; ++d)
    {
      const float v = p.velocity[d][i], a = p.acceleration[d][i];
      p.position[d][i] += dt * double(v) + 0.5 * dt * dt * double(a);
      const float base_v = euler ? v : p.velocity_previous[d][i];
      p.velocity_previous[d][i] = v;
      p.velocity[d][i] = base_v + dtv * a;
    }
  }
}

template <int dim>
void FluidSolver<dim>::predict_symplectic(double dt)
{
  auto& p = particles_;
  const std::size_t nb = p.n_boundary, n = p.size();
  const float half = float(0.5 * dt), rho0 = float(parameters_.reference_density);
  const float spray_fill = spray_fill_limit();
#pragma omp parallel for schedule(static) if (n > light_parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
  {
    p.density_previous[i] = p.density[i];
    const float rho = p.density[i] + half * p.density_rate[i];
    for (int d = 0; d < dim; ++d)
    {
      p.position_previous[d][i] = p.position[d][i];
      p.velocity_previous[d][i] = p.velocity[d][i];
    }
    if (i < nb)
    {
      p.density[i] = std::max(rho, rho0);
      continue;
    }
    p.density[i] = p.fill[i] < spray_fill ? std::max(rho, rho0) : rho;
    for (int d = 0; d < dim; ++d)
    {
      p.position[d][i] += 0.5 * dt * double(p.velocity[d][i]);
      p.velocity[d][i] += half * p.acceleration[d][i];
    }
  }
}

template <int dim>
void FluidSolver<dim>::correct_symplectic(double dt)
{
  auto& p = particles_;
  const std::size_t nb = p.n_boundary, n = p.size();
  const float rho0 = float(parameters_.reference_density);
  const float spray_fill = spray_fill_limit();
#pragma omp parallel for schedule(static) if (n > light_parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
  {
    const double eps = -double(p.density_rate[i]) / double(p.density[i]) * dt;
    const float rho = float(double(p.density_previous[i]) * (2 - eps) / (2 + eps));
    if (i < nb)
    {
      p.density[i] = std::max(rho, rho0);
      continue;
    }
    p.density[i] = p.fill[i] < spray_fill ? std::max(rho, rho0) : rho;
    for (int d = 0; d < dim; ++d)
    {
      const float v = p.velocity_previous[d][i] + float(dt) * p.acceleration[d][i];
      p.velocity[d][i] = v;
      p.position[d][i] =
          p.position_previous[d][i] + 0.5 * dt * (double(p.velocity_previous[d][i]) + double(v));
    }
  }
}

template <int dim>
std::size_t FluidSolver<dim>::memory_bytes() const
{
  return particles_.memory_bytes() + impl_->memory_bytes();
}

template struct LostParticle<2>;
template struct LostParticle<3>;
template class FluidSolver<2>;
template class FluidSolver<3>;
} // namespace chipflex::sph
