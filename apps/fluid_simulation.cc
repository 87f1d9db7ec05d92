#include "apps/fluid_simulation.h"

#include "common/hdf5_file.h"
#include "sph/particle_exchange.h"
#include "sph/probes.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace chipflex::apps
{
namespace
{
template <int dim>
std::string open_boundary_flow_text(const sph::OpenBoundary<dim>& z)
{
  std::ostringstream s;
  if (z.kind == sph::OpenBoundaryKind::inlet)
    s << "mean velocity " << z.velocity << " m/s ("
      << (z.profile == sph::InletProfile::parabolic ? "parabolic" : "uniform") << "), flow rate "
      << (z.flow_rate > 0 && z.profile == sph::InletProfile::uniform
              ? z.flow_rate
              : z.velocity * z.section_area())
      << (dim == 2 ? " m^2/s" : " m^3/s");
  else
    s << "pressure " << z.pressure << " Pa";
  return s.str();
}
} // namespace

template <int dim>
FluidSimulation<dim>::FluidSimulation(const sph::CaseDescription<dim>& description,
                                      const std::string& output_directory, bool distributed)
    : description_(description), fluid_(sph::build_fluid(description_)),
      walls_(output_directory, "walls")
{
  if (distributed)
  {
    auto exchange = std::make_shared<sph::ParticleExchange<dim>>();
    writes_ = exchange->rank() == 0;
    fluid_->distribute(exchange);
  }
}

template <int dim>
std::size_t FluidSimulation<dim>::n_fluid_particles() const
{
  fluid_->initialise();
  const auto* exchange = fluid_->exchange();
  if (!exchange)
    return fluid_->n_fluid();
  double n = double(fluid_->n_fluid() - fluid_->n_ghosts());
  exchange->sum(&n, 1);
  return std::size_t(n);
}

template <int dim>
ParticleFrame FluidSimulation<dim>::frame() const
{
  fluid_->initialise();
  std::vector<typename SurfaceOutput<dim>::Surface> walls;
  for (int id = 0; id < fluid_->n_walls(); ++id)
  {
    if (std::find(excluded_walls_.begin(), excluded_walls_.end(), id) != excluded_walls_.end())
      continue;
    const auto& w = fluid_->wall(id);
    walls.push_back({w.name,
                     w.vertices,
                     w.faces,
                     {{"velocity", "m/s", w.velocities},
                      {"fluid_force", dim == 2 ? "N/m" : "N", fluid_->wall_vertex_forces(id)}}});
  }
  // A fluid without walls (no tank) writes no walls.xdmf rather than an empty one.
  if (!walls.empty() && writes_)
    walls_.write(time(), walls);
  return particle_frame(*fluid_);
}

template <int dim>
std::vector<std::string> FluidSimulation<dim>::probe_columns() const
{
  std::vector<std::string> c;
  for (const auto& p : description_.pressure_probes)
    c.push_back("p_" + p.name + "_Pa");
  for (const auto& p : description_.height_probes)
    c.push_back("h_" + p.name + "_m");
  for (const auto& q : description_.flow_sections)
    c.push_back("q_" + q.name + (dim == 2 ? "_m2_s" : "_m3_s"));
  // Open boundaries: per zone the particles created and removed so far and the mass flow
  // through its buffer now (kg/s; 2D: kg/(s m)), then the totals.
  for (int k = 0; k < fluid_->n_open_boundaries(); ++k)
  {
    const std::string& name = fluid_->open_boundary(k).name;
    c.push_back(name + "_created");
    c.push_back(name + "_removed");
    c.push_back(name + "_mass_flow");
  }
  if (fluid_->n_open_boundaries() > 0)
  {
    c.push_back("inflow_particles");
    c.push_back("outflow_particles");
  }
  c.push_back("lost_particles");
  // The largest fluid speed at any step so far (every force pass, not only probe times).
  c.push_back("peak_fluid_speed_m_s");
  return c;
}

template <int dim>
std::vector<double> FluidSimulation<dim>::probe_values() const
{
  std::vector<double> v;
  for (const auto& p : description_.pressure_probes)
    v.push_back(sph::sample_pressure(*fluid_, p.position));
  for (const auto& p : description_.height_probes)
    v.push_back(sph::sample_water_height(*fluid_, p.position));
  for (const auto& q : description_.flow_sections)
    if constexpr (dim == 2)
      v.push_back(sph::sample_flow_rate(*fluid_, q.a, q.b));
    else
      v.push_back(sph::sample_flow_rate(*fluid_, q.point, q.normal));
  for (int k = 0; k < fluid_->n_open_boundaries(); ++k)
  {
    const auto flow = fluid_->open_boundary_flow(k);
    v.push_back(double(flow.created));
    v.push_back(double(flow.removed));
    v.push_back(flow.mass_flow);
  }
  if (fluid_->n_open_boundaries() > 0)
  {
    v.push_back(double(fluid_->n_inflow()));
    v.push_back(double(fluid_->n_outflow()));
  }
  v.push_back(double(fluid_->lost_particles().size()));
  v.push_back(fluid_->peak_fluid_speed());
  return v;
}

template <int dim>
void FluidSimulation<dim>::save(Hdf5File* file) const
{
  fluid_->save(file, "/fluid");
}

template <int dim>
void FluidSimulation<dim>::load(const Hdf5File& file)
{
  fluid_->load(file, "/fluid");
  walls_.resume(time());
}

template <int dim>
std::string FluidSimulation<dim>::summary() const
{
  fluid_->initialise();
  const auto& p = fluid_->parameters();
  std::ostringstream s;
  s << dim << "D SPH fluid: " << n_fluid_particles() << " fluid + " << fluid_->n_boundary()
    << " boundary particles, dp = " << p.particle_spacing << " m, h = " << p.smoothing_length()
    << " m, c0 = " << p.speed_of_sound << " m/s, " << fluid_->n_walls() << " wall(s), scheme "
    << (p.scheme == sph::TimeScheme::symplectic        ? "symplectic"
        : p.scheme == sph::TimeScheme::position_verlet ? "position verlet"
                                                       : "verlet")
    << "\n";
  if (const auto* exchange = fluid_->exchange())
  {
    const auto& slabs = exchange->decomposition();
    s << "MPI: " << exchange->n_ranks() << " ranks, slabs along "
      << "xyz"[slabs.axis()] << " cut at";
    for (int r = 1; r < exchange->n_ranks(); ++r)
      s << " " << slabs.lower(r);
    s << " m, halo " << slabs.halo_width() << " m";
    // Ranks beside an open boundary's buffer need more (sph/slab_decomposition.h).
    for (int r = 0; r < exchange->n_ranks(); ++r)
      if (slabs.halo_width(r) > slabs.halo_width())
        s << ", rank " << r << " " << slabs.halo_width(r) << " m";
    s << "\n";
  }
  for (int k = 0; k < fluid_->n_open_boundaries(); ++k)
  {
    const auto& z = fluid_->open_boundary(k);
    const char* axes = "xyz";
    s << "open boundary " << z.name << ": "
      << (z.kind == sph::OpenBoundaryKind::inlet ? "inlet" : "outlet") << " along "
      << (z.sign > 0 ? "+" : "-") << axes[z.axis] << ", plane at " << z.plane() << " m, "
      << std::lround(z.thickness() / p.particle_spacing) << " buffer layers, "
      << open_boundary_flow_text(z) << "\n";
  }
  if (p.shifting_coefficient > 0)
    s << "particle shifting: D = " << p.shifting_coefficient
      << " h |v| dt, none at free surfaces\n";
  if (p.summation_blend > 0)
    s << "density: continuity, moved " << p.summation_blend
      << " of the way to the kernel sum in every step (an internal flow)\n";
  if (p.background_pressure > 0)
  {
    s << "background pressure " << p.background_pressure
      << " Pa (added in the momentum equation; pressures in outputs, gauges and open "
         "boundaries are gauge)\n";
    // A Lennard-Jones wall has no particles to carry the background pressure: the fluid
    // next to it has a truncated support and is pressed into it.
    for (int w = 0; w < fluid_->n_walls(); ++w)
      if (fluid_->wall(w).model == sph::WallModel::lennard_jones && !fluid_->wall(w).fluid_passes)
        s << "warning: background pressure with the Lennard-Jones wall '" << fluid_->wall(w).name
          << "': it presses the fluid into the wall; give it `wall model = dummy particles` "
             "(a body or an extra wall may also be a `thin skin`; docs/sph.md, \"Background "
             "pressure\")\n";
  }
  s << "domain [" << p.domain_min.transpose() << "] - [" << p.domain_max.transpose() << "] m";
  return s.str();
}

template <int dim>
std::string FluidSimulation<dim>::flow_summary() const
{
  std::string s;
  if (fluid_->n_open_boundaries() > 0)
    s += " inflow_particles=" + std::to_string(fluid_->n_inflow()) +
         " outflow_particles=" + std::to_string(fluid_->n_outflow());
  // Thin skins: fluid particles the guard put back on their side (each would have
  // crossed a skin; sph/thin_skins.h).
  if (fluid_->has_thin_skins())
    s += " guarded_particles=" + std::to_string(fluid_->n_guarded());
  // Particle shifting measures the closest fluid pair after every step: a clumping check
  // (below 0.1 dp, two particles sit on one point). The particles beside a thin skin,
  // which are not shifted, have their own record.
  const auto& p = fluid_->parameters();
  const auto pair_keys = [&](const std::string& name, const sph::ClosestPairRecord<dim>& pair)
  {
    if (p.shifting_coefficient <= 0 || !pair.seen())
      return;
    std::ostringstream c;
    c.precision(3);
    c << " " << name << "_dp=" << pair.distance / p.particle_spacing << " " << name
      << "_t_s=" << pair.time << " " << name << "_at_m=";
    for (int d = 0; d < dim; ++d)
      c << (d ? "," : "") << pair.position[d];
    s += c.str();
  };
  pair_keys("closest_fluid_pair", fluid_->closest_fluid_pair());
  pair_keys("closest_skin_side_pair", fluid_->closest_skin_side_pair());
  // Under a background pressure: how much of the fluid went into tension (the
  // background pressure did not cover the suction there).
  if (p.background_pressure > 0)
  {
    std::ostringstream c;
    c.precision(3);
    c << " tension_peak_percent=" << 100 * fluid_->tension_peak_fraction()
      << " tension_peak_t_s=" << fluid_->tension_peak_time();
    if (fluid_->lowest_absolute_pressure() < 1e300)
      c << " lowest_absolute_pressure_pa=" << fluid_->lowest_absolute_pressure();
    s += c.str();
  }
  return s;
}

template <int dim>
std::string FluidSimulation<dim>::flow_warnings() const
{
  const auto& p = fluid_->parameters();
  std::ostringstream s;
  s.precision(3);
  if (p.background_pressure > 0 && fluid_->tension_peak_fraction() > tension_warning_fraction)
    s << "warning: " << 100 * fluid_->tension_peak_fraction()
      << " % of the fluid was in tension (a mean over 100 h / c0) at t = "
      << fluid_->tension_peak_time() << " s (absolute pressure below 0, the lowest "
      << fluid_->lowest_absolute_pressure() << " Pa): the background pressure of "
      << p.background_pressure
      << " Pa does not cover the flow's suction, and particles in tension pull each other "
         "into pairs (clumping); raise the background pressure (docs/sph.md, \"Background "
         "pressure\", \"Tension\")\n";
  const auto clumped = [&](const sph::ClosestPairRecord<dim>& pair, const char* where)
  {
    if (p.shifting_coefficient <= 0 || !pair.seen() ||
        pair.distance >= clumping_warning_distance * p.particle_spacing)
      return;
    s << "warning: two fluid particles" << where << " came within "
      << pair.distance / p.particle_spacing << " dp of each other at t = " << pair.time
      << " s at (";
    for (int d = 0; d < dim; ++d)
      s << (d ? ", " : "") << pair.position[d];
    s << "): particles clump there (closer than " << clumping_warning_distance
      << " dp, their mutual pressure force vanishes), and the pressure there is noisy "
         "(docs/sph.md, \"Particle shifting\")\n";
  };
  clumped(fluid_->closest_fluid_pair(),
          fluid_->has_thin_skins() ? " away from the thin skins" : "");
  clumped(fluid_->closest_skin_side_pair(), " beside a thin skin");
  std::string all = s.str();
  if (!all.empty())
    all.pop_back(); // the last line's newline: the caller ends the lines it writes
  return all;
}

template <int dim>
std::string FluidSimulation<dim>::mass_balance(std::size_t start_fluid_particles) const
{
  if (fluid_->n_open_boundaries() == 0)
    return "";
  // Every fluid particle carries the same constant mass, so the balance is a count: what
  // the inlets created, the zones removed and the run lost, against what the domain (its
  // buffers included) holds more than at the start. A particle that vanished or appeared
  // outside these paths would show as a residual.
  const double m = fluid_->particle_mass();
  const double in = double(fluid_->n_inflow()), out = double(fluid_->n_outflow()),
               lost = double(fluid_->lost_particles().size()),
               stored = double(n_fluid_particles()) - double(start_fluid_particles);
  std::ostringstream s;
  s.precision(9);
  s << "mass_balance: in_kg=" << m * in << " out_kg=" << m * out << " lost_kg=" << m * lost
    << " stored_change_kg=" << m * stored << " residual_kg=" << m * (in - out - lost - stored)
    << " residual_particles=" << std::int64_t(in - out - lost - stored);
  return s.str();
}

template <int dim>
std::string FluidSimulation<dim>::peak_fluid_speed_where() const
{
  std::ostringstream s;
  s << "t = " << fluid_->peak_fluid_speed_time() << " s at (";
  for (int d = 0; d < dim; ++d)
    s << (d ? ", " : "") << fluid_->peak_fluid_speed_position()[d];
  s << ")";
  return s.str();
}

template class FluidSimulation<2>;
template class FluidSimulation<3>;
} // namespace chipflex::apps
