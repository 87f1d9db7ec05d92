// FluidSolver: neighbour sorting and the force pass (fluid, dummy walls, Lennard-Jones
// walls, gravity), with the pair policies chosen once at set-up.

#include "common/input_error.h"
#include "sph/fluid_solver_impl.h"
#include "sph/particle_exchange.h"

#include <cmath>
#include <sstream>

namespace chipflex::sph
{
namespace
{
template <int dim, bool count_fill, bool sided, bool shifting, class Viscosity, class Diffusion>
float run_pass(const ForcePassInput<dim>& in, const PairPolicies& policies, std::size_t nb,
               std::size_t n)
{
  const auto& visc = policies.get<Viscosity>();
  const auto& diff = policies.get<Diffusion>();
  return force_pass<dim, count_fill, sided, shifting>(in, visc, diff, nb, n);
}

template <int dim, bool count_fill, bool sided, bool shifting, class Viscosity>
auto select_diffusion(DensityDiffusionModel model)
{
  switch (model)
  {
  case DensityDiffusionModel::none:
    return &run_pass<dim, count_fill, sided, shifting, Viscosity, NoDensityDiffusion>;
  case DensityDiffusionModel::molteni_colagrossi:
    return &run_pass<dim, count_fill, sided, shifting, Viscosity, MolteniColagrossiDiffusion>;
  default:
    return &run_pass<dim, count_fill, sided, shifting, Viscosity, FourtakasDiffusion>;
  }
}

template <int dim, bool count_fill, bool sided, bool shifting>
auto select_viscosity(const FluidParameters<dim>& p)
{
  return p.viscosity == ViscosityModel::artificial
             ? select_diffusion<dim, count_fill, sided, shifting, ArtificialViscosity>(
                   p.density_diffusion)
             : select_diffusion<dim, count_fill, sided, shifting, LaminarViscosity>(
                   p.density_diffusion);
}

template <int dim, bool count_fill, bool sided>
auto select_shifting(const FluidParameters<dim>& p)
{
  return p.shifting_coefficient > 0 ? select_viscosity<dim, count_fill, sided, true>(p)
                                    : select_viscosity<dim, count_fill, sided, false>(p);
}
} // namespace

template <int dim>
void FluidSolver<dim>::Impl::setup(const FluidParameters<dim>& p, bool sided)
{
  const double h = p.smoothing_length(), c0 = p.speed_of_sound;
  grid.setup(p.domain_min, p.domain_max, 2 * h);
  eos = TaitEquationOfState(p.reference_density, c0, p.gamma);
  kernel_factor = float(WendlandKernel<dim>(h).gradient_factor);
  // Lattice points strictly inside the support 2h of a lattice point (itself included).
  const int reach = int(std::ceil(2 * h / p.particle_spacing));
  long full = 0;
  double lattice_sum = 0;
  for (int a = -reach; a <= reach; ++a)
    for (int b = -reach; b <= reach; ++b)
      for (int c = dim == 3 ? -reach : 0; c <= (dim == 3 ? reach : 0); ++c)
      {
        const double r2 = (a * a + b * b + c * c) * p.particle_spacing * p.particle_spacing;
        full += r2 < 4 * h * h;
        const double t = std::max(0.0, 1 - std::sqrt(r2) / (2 * h));
        lattice_sum += t * t * t * t * (5 - 4 * t);
      }
  inverse_lattice_sum = 1 / lattice_sum;
  fill_factor = float(1.0 / double(full));
  const float eta2 = float(0.01 * h * h);
  policies.artificial = {float(-2 * p.artificial_viscosity * c0 * h), eta2};
  policies.laminar = {float(4 * p.kinematic_viscosity), eta2};
  const float two_delta_h_c0 = float(2 * p.density_diffusion_delta * h * c0);
  policies.molteni_colagrossi.two_delta_h_c0 = two_delta_h_c0;
  policies.fourtakas.two_delta_h_c0 = two_delta_h_c0;
  for (int d = 0; d < 3; ++d)
    policies.fourtakas.g_over_c2[d] =
        d < dim ? float(p.reference_density * p.gravity[d] / (c0 * c0)) : 0.0f;
  // The spray filling costs ~8 % of the force loop, the thin skins' visibility mask
  // and particle shifting more: each is compiled in only where it is used.
  if (sided)
    pass = p.cut_spray_tension ? select_shifting<dim, true, true>(p)
                               : select_shifting<dim, false, true>(p);
  else
    pass = p.cut_spray_tension ? select_shifting<dim, true, false>(p)
                               : select_shifting<dim, false, false>(p);
  // The force loop forms W(r) / alpha = t^4 (5 - 4t) from its t; W(dp) from the kernel.
  const WendlandKernel<dim> kernel(h);
  inverse_w_dp = float(kernel.alpha / kernel.value(p.particle_spacing));
}

template <int dim>
void FluidSolver<dim>::sort_and_bin()
{
  auto& p = particles_;
  auto& g = impl_->grid;
  const std::size_t nb = p.n_boundary, n = p.size();
  const std::size_t first = boundary_moved_ ? 0 : nb;
  std::size_t n_bad = 0;
  const float rho_min = float(parameters_.minimum_density_ratio * parameters_.reference_density);
  const float rho_max = float(parameters_.maximum_density_ratio * parameters_.reference_density);
#pragma omp parallel for schedule(static) reduction(+ : n_bad) if (n > light_parallel_threshold)
  for (std::size_t i = first; i < n; ++i)
  {
    double x[dim];
    for (int d = 0; d < dim; ++d)
      x[d] = p.position[d][i];
    const std::uint32_t c = g.cell_of(x); // outside also for a NaN position
    p.cell[i] = c;
    const float rho = p.density[i];
    bool ok = i < nb || (rho >= rho_min && rho <= rho_max); // false for NaN
    for (int d = 0; d < dim; ++d)
      ok = ok && std::isfinite(p.velocity[d][i]);
    n_bad += c == NeighbourGrid<dim>::outside || !ok;
  }
  if (n_bad > 0)
    remove_lost_particles();
  if (boundary_moved_)
  {
    g.sort(p.cell, 0, nb, impl_->permutation, impl_->boundary_start);
    p.permute(0, impl_->permutation, impl_->scratch);
    boundary_moved_ = false;
  }
  g.sort(p.cell, nb, p.size(), impl_->permutation, impl_->fluid_start);
  p.permute(nb, impl_->permutation, impl_->scratch);
  if (walls_moved_)
  {
    std::vector<const WallSurface<dim>*> lj(walls_.size(), nullptr);
    for (std::size_t w = 0; w < walls_.size(); ++w)
      if (walls_[w].model == WallModel::lennard_jones && !walls_[w].fluid_passes)
        lj[w] = &walls_[w];
    impl_->lennard_jones.bin(lj, g);
    walls_moved_ = false;
  }
}

template <int dim>
void FluidSolver<dim>::label_thin_skin_sides()
{
  auto& im = *impl_;
  if (walls_moved_ || !im.thin_skins_binned)
  {
    std::vector<const WallSurface<dim>*> thin(walls_.size(), nullptr);
    for (std::size_t w = 0; w < walls_.size(); ++w)
      if (walls_[w].model == WallModel::thin_skin && !walls_[w].fluid_passes)
        thin[w] = &walls_[w];
    // A fluid particle needs its side where a dummy particle of either side can reach
    // it: the kernel support plus the layers' depth.
    int layers = 0;
    for (const auto& w : walls_)
      layers = std::max(layers, w.dummy_layers > 0
                                    ? w.dummy_layers
                                    : int(std::ceil(2 * h_ / parameters_.particle_spacing)));
    const double reach = 2 * h_ + layers * parameters_.particle_spacing;
    im.thin_skins.bin(thin, im.wall_closed, im.grid, reach, parameters_.particle_spacing);
    im.thin_skins_binned = true;
    if (im.thin_dummy.empty())
    {
      im.thin_dummy.assign(im.attachments.size(), 0);
      for (std::size_t k = 0; k < im.attachments.size(); ++k)
        im.thin_dummy[k] = im.attachments[k].wall != WallAttachment<dim>::no_wall &&
                           thin[im.attachments[k].wall] != nullptr;
    }
    im.thin_skins.label_boundary(particles_, im.grid, im.thin_dummy);
  }
  im.n_guarded +=
      im.thin_skins.label_fluid(particles_, particles_.n_boundary, particles_.size(), im.grid,
                                0.25 * parameters_.particle_spacing, mass_, dt_, im.guard_forces);
}

template <int dim>
void FluidSolver<dim>::record_tension()
{
  const auto& p = particles_;
  const std::size_t nb = p.n_boundary, n = p.size();
  std::size_t fluid = 0, tense = 0;
  double lowest = lowest_absolute_pressure_;
  // Owned fluid particles outside the buffers (the open boundaries set those); the
  // absolute pressure is the pressure term times rho^2.
  for (std::size_t i = nb; i < n; ++i)
  {
    if (p.is_ghost(i) || (!p.zone.empty() && p.zone[i] != 0))
      continue;
    const double absolute = double(p.pressure_term[i]) * double(p.density[i]) * p.density[i];
    ++fluid;
    tense += absolute < 0 ? 1 : 0;
    lowest = std::min(lowest, absolute);
  }
  lowest_absolute_pressure_ = lowest;
  // The fraction's running mean over about 100 h / c0 (a hundred times the sound's
  // crossing of a kernel support): tension that lasts, not the few steps of tension
  // in which a starting lattice settles beside a curved wall (1 % of FSI2's fluid for
  // 3 ms) or a pressure wave passes.
  const double fraction = fluid > 0 ? double(tense) / double(fluid) : 0.0;
  const double tau = 100 * h_ / parameters_.speed_of_sound;
  const double weight = std::min(1.0, std::max(0.0, time_ - tension_mean_time_) / tau);
  tension_mean_ += weight * (fraction - tension_mean_);
  tension_mean_time_ = time_;
  if (tension_mean_ > tension_peak_)
  {
    tension_peak_ = tension_mean_;
    tension_peak_time_ = time_;
  }
}

template <int dim>
void FluidSolver<dim>::force_pass()
{
  if (!particles_.skin.empty())
    label_thin_skin_sides();
  sort_and_bin();
  if (!zones_.empty())
    prescribe_open_boundaries();
  collect_walls_from_fluid();
  if (!impl_->walls_from_fluid.empty())
    extrapolate_wall_densities();
  if (parameters_.no_slip_walls)
    mirror_wall_velocities();
  if (parameters_.summation_blend > 0)
  {
    sum_densities();
    // The owners' densities moved after this step's exchange: the ghosts take them again,
    // or a pair across two ranks would see two pressures for one particle.
    if (exchange_)
      exchange_->refresh_ghosts(particles_, true);
  }
  auto& p = particles_;
  auto& im = *impl_;
  const std::size_t nb = p.n_boundary, n = p.size();
  const float mass = float(mass_);
  const float p_min = float(std::max(parameters_.minimum_pressure, -1e30));
  const float p_background = float(parameters_.background_pressure);
#pragma omp parallel for schedule(static) if (n > light_parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
  {
    const float rho = p.density[i];
    const float pressure = std::max(im.eos.pressure(rho), p_min) + p_background;
    p.pressure_term[i] = pressure / (rho * rho);
    p.volume[i] = mass / rho;
  }
  if (p_background > 0)
    record_tension();
  ForcePassInput<dim> in;
  for (int d = 0; d < dim; ++d)
  {
    in.x[d] = p.position[d].data();
    in.v[d] = p.velocity[d].data();
    in.a[d] = p.acceleration[d].data();
  }
  in.rho = p.density.data();
  in.pressure_term = p.pressure_term.data();
  in.volume = p.volume.data();
  in.cell = p.cell.data();
  in.fluid_start = im.fluid_start.data();
  in.boundary_start = im.boundary_start.data();
  in.rows = im.grid.row_offsets().data();
  in.inverse_h = float(1 / h_);
  in.kernel_factor = im.kernel_factor;
  in.mass_fluid = in.mass_boundary = mass;
  in.density_rate = p.density_rate.data();
  in.fill = p.fill.data();
  for (int d = 0; d < dim; ++d)
    in.side[d] = p.side[d].data();
  in.skin = p.skin.data();
  in.fill_factor = im.fill_factor;
  in.inverse_w_dp = im.inverse_w_dp;
  in.boundary_volume = float(mass_ / parameters_.reference_density);
  if (parameters_.shifting_coefficient > 0)
  {
    for (int d = 0; d < dim; ++d)
    {
      im.shift_sum[d].resize(n - nb);
      in.shift_sum[d] = im.shift_sum[d].data();
    }
    im.position_divergence.resize(n - nb);
    im.closest.resize(n - nb);
    in.position_divergence = im.position_divergence.data();
    in.closest = im.closest.data();
  }
  if (exchange_)
  {
    // Ghosts' own sums, and those of wall particles that no owned particle sees, would
    // be thrown away: skip them (a ghost keeps the filling its owner sent).
    const SlabDecomposition& slabs = exchange_->decomposition();
    const double reach = im.grid.cell_size();
    im.active.resize(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      const double s = p.position[slabs.axis()][i];
      im.active[i] = i < nb ? s >= slabs.lower(exchange_->rank()) - reach &&
                                  s < slabs.upper(exchange_->rank()) + reach
                            : !p.is_ghost(i);
    }
    in.active = im.active.data();
  }
  dot_rr2_max_ = im.pass(in, im.policies, nb, n);
  if (exchange_)
    for (std::size_t i = 0; i < n; ++i)
      if (!im.active[i])
      {
        p.density_rate[i] = 0;
        for (int d = 0; d < dim; ++d)
          p.acceleration[d][i] = 0;
      }

  for (std::size_t w = 0; w < vertex_forces_.size(); ++w)
    for (std::size_t k = 0; k < vertex_forces_[w].size(); ++k)
      vertex_forces_[w][k] = im.guard_forces[w][k];
  // Dummy-wall reactions, in boundary particle order (deterministic). Over MPI the ranks
  // beside a cut both compute the wall particles near it: each reaction counts on the
  // rank that owns the particle's position, and the ranks' sums add up below.
  for (std::size_t i = 0; i < nb; ++i)
  {
    const auto& a = im.attachments[p.id[i]];
    if (a.wall == WallAttachment<dim>::no_wall)
      continue;
    if (exchange_)
    {
      double x[dim];
      for (int d = 0; d < dim; ++d)
        x[d] = p.position[d][i];
      if (exchange_->decomposition().owner(x) != exchange_->rank())
        continue;
    }
    Vector f;
    for (int d = 0; d < dim; ++d)
      f[d] = mass_ * double(p.acceleration[d][i]);
    const auto& face = walls_[a.wall].faces[a.face];
    for (int k = 0; k < dim; ++k)
      vertex_forces_[a.wall][face[k]] += a.weights[k] * f;
  }
  im.lennard_jones.apply(p, nb, n, mass_, vertex_forces_);
  if (exchange_)
    sum_vertex_forces_over_ranks();

  // A turning frame: -Omega x (Omega x r) - 2 Omega x v - dOmega/dt x r on the fluid (the
  // walls stand still in it). A separate pass, so that the common case keeps its loop.
  if (parameters_.rotating_frame.active())
  {
    const RotatingFrame::Instant frame = parameters_.rotating_frame.at(force_time_);
#pragma omp parallel for schedule(static) if (n > light_parallel_threshold)
    for (std::size_t i = nb; i < n; ++i)
    {
      Vector x, v;
      for (int d = 0; d < dim; ++d)
      {
        x[d] = p.position[d][i];
        v[d] = p.velocity[d][i];
      }
      const Vector a = frame.acceleration<dim>(x, v);
      for (int d = 0; d < dim; ++d)
        p.acceleration[d][i] += float(a[d]);
    }
  }

  // Gravity, the largest acceleration for the time step, the fastest particle.
  float g[dim];
  for (int d = 0; d < dim; ++d)
    g[d] = float(parameters_.gravity[d]);
  float a2_max = 0, v2_max = 0;
  // Over MPI a ghost's own sums miss the neighbours beyond this rank's halo.
  const std::uint32_t* halo = p.halo.empty() ? nullptr : p.halo.data();
#pragma omp parallel for schedule(static)                                                          \
    reduction(max                                                                                  \
              : a2_max, v2_max) if (n > light_parallel_threshold)
  for (std::size_t i = nb; i < n; ++i)
  {
    float a2 = 0, v2 = 0;
    for (int d = 0; d < dim; ++d)
    {
      const float a = p.acceleration[d][i] + g[d];
      p.acceleration[d][i] = a;
      a2 += a * a;
      v2 += p.velocity[d][i] * p.velocity[d][i];
    }
    const bool own = !halo || halo[i] < ParticleArrays<dim>::ghost_flag;
    a2_max = std::max(a2_max, own ? a2 : 0.0f);
    v2_max = std::max(v2_max, v2);
  }
  acceleration_max_ = std::sqrt(double(a2_max));
  if (std::sqrt(double(v2_max)) > peak_speed_)
  {
    peak_speed_ = std::sqrt(double(v2_max));
    peak_speed_time_ = time_;
    for (std::size_t i = nb; i < n; ++i) // rare after the start: the first fastest one
    {
      float v2 = 0;
      for (int d = 0; d < dim; ++d)
        v2 += p.velocity[d][i] * p.velocity[d][i];
      if (v2 == v2_max)
      {
        for (int d = 0; d < dim; ++d)
          peak_speed_position_[d] = double(p.position[d][i]);
        break;
      }
    }
  }
  const bool blew_up = !(acceleration_max_ < 1e300); // NaN or infinite
  if (exchange_) // the time step is the global one, and so is the stop
  {
    double maxima[3] = {blew_up ? 0.0 : acceleration_max_, double(dot_rr2_max_), blew_up ? 1.0 : 0};
    exchange_->maximum(maxima, 3);
    acceleration_max_ = maxima[0];
    dot_rr2_max_ = float(maxima[1]);
    if (maxima[2] > 0 && !blew_up)
    {
      std::ostringstream s;
      s.precision(6);
      s << "step " << step_ << ", t = " << time_
        << " s: a fluid particle of another rank has a non-finite acceleration (the run blew up)";
      throw SimulationError(s.str());
    }
  }
  if (blew_up) // name the first culprit
    for (std::size_t i = nb; i < n; ++i)
      for (int d = 0; d < dim; ++d)
        if (!std::isfinite(p.acceleration[d][i]))
          fail(i, "has a non-finite acceleration (the run blew up)");
  if (!zones_.empty())
    freeze_open_boundaries();
  for (const std::uint32_t i : im.walls_from_fluid)
    p.density_rate[i] = 0;
}

template void FluidSolver<2>::Impl::setup(const FluidParameters<2>&, bool);
template void FluidSolver<3>::Impl::setup(const FluidParameters<3>&, bool);
template void FluidSolver<2>::sort_and_bin();
template void FluidSolver<3>::sort_and_bin();
template void FluidSolver<2>::force_pass();
template void FluidSolver<3>::force_pass();
} // namespace chipflex::sph
