// FluidSolver: inlet and outlet buffer zones (sph/open_boundary.h). Everything here runs
// outside the force loop, and only when the case has zones:
//   transfer_open_boundaries()  step start: buffer <-> fluid transitions, new inlet
//                               particles, outflow removals (order-preserving);
//   prescribe_open_boundaries() after each sort: buffer velocity and density, prescribed
//                               or extrapolated from the fluid at the mirror point;
//   freeze_open_boundaries()    after each pass: buffer rates zeroed, so every time
//                               scheme moves a buffer particle by dt times its
//                               prescribed velocity and keeps its density (and the
//                               wall particles beside a buffer theirs).

#include "common/input_error.h"
#include "sph/fluid_solver_impl.h"
#include "sph/mirror_fit.h"
#include "sph/particle_exchange.h"

#include <cmath>
#include <sstream>

namespace chipflex::sph
{
template <int dim>
void FluidSolver<dim>::add_open_boundary(const OpenBoundary<dim>& zone)
{
  if (set_up_)
    throw std::logic_error("FluidSolver: open boundaries can only be added before the first step");
  const std::string where = "open boundaries/" + zone.name;
  const double dp = parameters_.particle_spacing;
  if (zone.axis < 0 || zone.axis >= dim || (zone.sign != 1 && zone.sign != -1))
    throw InputError(where, "the direction must be +x, -x, +y, -y" +
                                std::string(dim == 3 ? ", +z or -z" : " or "));
  if (!((zone.box_max - zone.box_min).minCoeff() > 0))
    throw InputError(where, "the box's max corner must exceed its min corner");
  // The new particle replaces the crossing one a buffer thickness upstream: a whole
  // number of spacings keeps the lattice rows continuous. The fluid next to the plane
  // needs a full kernel support of buffer.
  const double layers = zone.thickness() / dp;
  if (std::abs(layers - std::round(layers)) > 1e-6 * std::max(1.0, layers))
    throw InputError(where, "the box depth along the flow (" + std::to_string(zone.thickness()) +
                                " m) must be a whole number of particle spacings");
  if (std::round(layers) * dp < 2 * h_ * (1 - 1e-9))
    throw InputError(
        where, "the buffer needs at least " + std::to_string(int(std::ceil(2 * h_ / dp - 1e-9))) +
                   " layers (the kernel support 2h = " + std::to_string(2 * h_) + " m)");
  for (int d = 0; d < dim; ++d)
    if (zone.box_min[d] < parameters_.domain_min[d] || zone.box_max[d] > parameters_.domain_max[d])
      throw InputError(where, "the box must lie inside the domain box");
  if (zone.kind == OpenBoundaryKind::inlet && !(zone.velocity > 0))
    throw InputError(where, "the inlet velocity (or flow rate) must be positive");
  if (zone.ramp_time < 0)
    throw InputError(where, "the ramp time must not be negative");
  if (zones_.size() >= zone_index_mask)
    throw InputError(where, "at most 127 open boundaries");
  zones_.push_back(zone);
  zone_created_.push_back(0);
  zone_removed_.push_back(0);
}

template <int dim>
void FluidSolver<dim>::transfer_open_boundaries()
{
  auto& p = particles_;
  const std::size_t nb = p.n_boundary, n = p.size();
  std::vector<std::size_t> gone;
  struct Birth
  {
    double x[dim];
    float rho;
    std::uint8_t zone;
  };
  std::vector<Birth> births;
  // This step's counts: over MPI the ranks add theirs up below.
  std::vector<std::int64_t> created(zones_.size(), 0), removed(zones_.size(), 0);
  for (std::size_t i = nb; i < n; ++i)
  {
    if (p.is_ghost(i)) // last step's copy of another rank's particle: its owner decides
      continue;
    double x[dim];
    for (int d = 0; d < dim; ++d)
      x[d] = p.position[d][i];
    const std::uint8_t flag = p.zone[i], z = flag & zone_index_mask;
    if (z > 0)
    {
      const auto& zone = zones_[z - 1];
      const double depth = zone.depth(x);
      if (zone.kind == OpenBoundaryKind::inlet)
      {
        if (depth <= 0 && (flag & zone_respawned)) // its replacement exists already
          p.zone[i] = 0;
        else if (depth <= 0) // into the fluid: a new buffer particle one thickness upstream
        {
          p.zone[i] = 0;
          Birth b;
          for (int d = 0; d < dim; ++d)
            b.x[d] = x[d];
          b.x[zone.axis] -= zone.sign * zone.thickness();
          b.rho = p.density[i];
          b.zone = z;
          births.push_back(b);
        }
        else if (depth > zone.thickness()) // pushed back out (cannot happen with u > 0)
        {
          gone.push_back(i);
          ++removed[z - 1];
        }
      }
      else if (depth > zone.thickness()) // out through the far face: outflow
      {
        gone.push_back(i);
        ++removed[z - 1];
      }
      else if (depth <= 0 || !zone.in_section(x)) // back into the fluid
        p.zone[i] = 0;
      continue;
    }
    for (std::size_t k = 0; k < zones_.size(); ++k)
    {
      const auto& zone = zones_[k];
      const double depth = zone.depth(x);
      if (depth <= 0 || !zone.in_section(x))
        continue;
      const bool inlet = zone.kind == OpenBoundaryKind::inlet;
      if ((inlet && depth > parameters_.particle_spacing) || depth > zone.thickness())
      {
        // Fluid flowing deep into a full inlet buffer would overlap its particles: it
        // leaves the run through that zone.
        gone.push_back(i);
        ++removed[k];
      }
      else
      {
        // Back into an inlet within a spacing (a slow particle next to a wall that has
        // just crossed and jiggles back): a buffer particle again, whose replacement
        // already exists. Removing it instead loses fluid at every such jiggle (4 % of
        // the flow in the no-slip Poiseuille channel).
        p.zone[i] = std::uint8_t((k + 1) | (inlet ? zone_respawned : 0));
        // position verlet reuses the last pass's rates in its predictor.
        for (int d = 0; d < dim; ++d)
          p.acceleration[d][i] = 0;
        p.density_rate[i] = 0;
      }
      break;
    }
  }
  p.remove(gone);
  for (const auto& b : births)
    ++created[b.zone - 1];
  // Ids follow the births: over MPI rank 0's first, then rank 1's, and so on.
  std::size_t id = n_fluid_created_;
  if (exchange_)
    id = share_open_boundary_counts(births.size(), created, removed);
  else
  {
    n_fluid_created_ += births.size();
    for (std::size_t k = 0; k < zones_.size(); ++k)
    {
      zone_created_[k] += created[k];
      zone_removed_[k] += removed[k];
    }
  }
  // The counts are the same on every rank, so all stop alike.
  if (n_fluid_created_ > std::size_t(0xffffffffu))
    throw SimulationError("the inlets have created 2^32 particles, more than ids hold");
  for (const auto& b : births)
  {
    const auto& zone = zones_[b.zone - 1];
    float v[dim];
    for (int d = 0; d < dim; ++d)
      v[d] = 0;
    v[zone.axis] = float(zone.sign * zone.speed(b.x, time_));
    p.append(b.x, v, b.rho, std::uint32_t(id++), b.zone);
  }
}

template <int dim>
void FluidSolver<dim>::prescribe_open_boundaries()
{
  auto& p = particles_;
  auto& im = *impl_;
  const std::size_t nb = p.n_boundary, n = p.size();
  const WendlandKernel<dim> W(h_);
  const double rho_lo = parameters_.minimum_density_ratio * parameters_.reference_density;
  const double rho_hi = parameters_.maximum_density_ratio * parameters_.reference_density;
  const double rho0 = parameters_.reference_density;
  // A buffer particle's fit reads fluid particles only, so the order of the writes does
  // not matter: the result is the same for any thread count.
  for (std::size_t i = nb; i < n; ++i)
  {
    const std::uint8_t z = p.zone[i] & zone_index_mask;
    if (!z || p.is_ghost(i)) // a ghost takes its owner's values (below)
      continue;
    const auto& zone = zones_[z - 1];
    Vector x;
    for (int d = 0; d < dim; ++d)
      x[d] = p.position[d][i];
    const double depth = zone.depth(x.data());
    // The mirror point: as far inside the fluid as the particle is inside the buffer.
    const Vector xg = x + 2 * depth * zone.into_fluid();
    const auto fit = fit_at<dim>(p, im.grid, im.fluid_start, W, mass_, xg, true);
    Vector v = velocity(i);
    double rho = p.density[i];
    if (zone.kind == OpenBoundaryKind::inlet)
    {
      v.setZero();
      v[zone.axis] = zone.sign * zone.speed(x.data(), time_);
      if (fit.valid)
        rho = std::clamp(fit.density + (x - xg).dot(fit.density_gradient), rho_lo, rho_hi);
    }
    else
    {
      // Pressure at the section centre plus the hydrostatic part across the section.
      Vector centre = 0.5 * (zone.box_min + zone.box_max);
      centre[zone.axis] = zone.plane();
      const double pressure = zone.pressure + rho0 * parameters_.gravity.dot(x - centre);
      rho = std::clamp(im.eos.density(pressure), rho_lo, rho_hi);
      if (fit.valid)
        v = fit.velocity; // zero normal gradient: a developed outflow
    }
    for (int d = 0; d < dim; ++d)
      p.velocity[d][i] = p.velocity_previous[d][i] = float(v[d]);
    p.density[i] = p.density_previous[i] = float(rho);
  }
  // Over MPI the owners hold the whole fit's fluid (the halo is wide enough,
  // exchange_halo_width); a ghost's fit would miss part of it.
  if (exchange_)
    exchange_->refresh_ghosts(p, true);

  // Walls beside an outlet's buffer (a channel's walls reaching into or past it): near the
  // buffer's far face their dummy particles see the buffer's particles arrive from
  // upstream only, so their continuity sum compresses them without end (1,551 kg/m^3
  // within 0.1 s in a test channel), and with a background pressure the buffer particles
  // beside them then cut the time step (the 2D flute at 50 kPa took about 40 times the
  // steps). They take the density of the outlet's prescribed pressure at their place and
  // keep it through the step, as the buffer particles do (docs/sph.md, "Walls at open
  // ends").
  im.walls_beside_buffers.clear();
  const double reach = 2 * h_ + parameters_.particle_spacing;
  for (std::size_t i = 0; i < nb; ++i)
  {
    Vector x;
    for (int d = 0; d < dim; ++d)
      x[d] = p.position[d][i];
    for (const auto& zone : zones_)
    {
      const double depth = zone.depth(x.data());
      bool beside =
          zone.kind == OpenBoundaryKind::outlet && depth >= 0 && depth <= zone.thickness() + reach;
      for (int d = 0; d < dim; ++d)
        beside = beside && (d == zone.axis ||
                            (x[d] >= zone.box_min[d] - reach && x[d] <= zone.box_max[d] + reach));
      if (!beside)
        continue;
      Vector centre = 0.5 * (zone.box_min + zone.box_max);
      centre[zone.axis] = zone.plane();
      const double pressure = zone.pressure + rho0 * parameters_.gravity.dot(x - centre);
      const double rho = std::clamp(im.eos.density(pressure), rho_lo, rho_hi);
      p.density[i] = p.density_previous[i] = float(rho);
      im.walls_beside_buffers.push_back(std::uint32_t(i));
      break;
    }
  }
}

template <int dim>
void FluidSolver<dim>::freeze_open_boundaries()
{
  auto& p = particles_;
  for (std::size_t i = p.n_boundary; i < p.size(); ++i)
    if (p.zone[i])
    {
      for (int d = 0; d < dim; ++d)
        p.acceleration[d][i] = 0;
      p.density_rate[i] = 0;
    }
  for (const std::uint32_t i : impl_->walls_beside_buffers)
    p.density_rate[i] = 0;
}

template <int dim>
OpenBoundaryFlow FluidSolver<dim>::open_boundary_flow(int k) const
{
  const auto& zone = zones_.at(k);
  OpenBoundaryFlow flow;
  flow.created = zone_created_[k];
  flow.removed = zone_removed_[k];
  const auto& p = particles_;
  double sums[2] = {0, 0}; // velocity along the flow, particles
  if (set_up_)
    for (std::size_t i = p.n_boundary; i < p.size(); ++i)
      if ((p.zone[i] & zone_index_mask) == k + 1 && !p.is_ghost(i))
      {
        sums[0] += zone.sign * double(p.velocity[zone.axis][i]);
        sums[1] += 1;
      }
  if (exchange_) // collective: every rank asks alike
    exchange_->sum(sums, 2);
  flow.buffer_particles = std::size_t(sums[1]);
  flow.mass_flow = mass_ * sums[0] / zone.thickness();
  return flow;
}

template <int dim>
std::size_t FluidSolver<dim>::n_inflow() const
{
  std::int64_t s = 0;
  for (auto c : zone_created_)
    s += c;
  return std::size_t(s);
}

template <int dim>
std::size_t FluidSolver<dim>::n_outflow() const
{
  std::int64_t s = 0;
  for (auto c : zone_removed_)
    s += c;
  return std::size_t(s);
}

#define CHIPFLEX_INSTANTIATE(D)                                                                    \
  template void FluidSolver<D>::add_open_boundary(const OpenBoundary<D>&);                         \
  template void FluidSolver<D>::transfer_open_boundaries();                                        \
  template void FluidSolver<D>::prescribe_open_boundaries();                                       \
  template void FluidSolver<D>::freeze_open_boundaries();                                          \
  template OpenBoundaryFlow FluidSolver<D>::open_boundary_flow(int) const;                         \
  template std::size_t FluidSolver<D>::n_inflow() const;                                           \
  template std::size_t FluidSolver<D>::n_outflow() const;
CHIPFLEX_INSTANTIATE(2)
CHIPFLEX_INSTANTIATE(3)
#undef CHIPFLEX_INSTANTIATE
} // namespace chipflex::sph
