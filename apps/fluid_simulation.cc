#include "apps/fluid_simulation.h"

#include "common/hdf5_file.h"
#include "sph/probes.h"

#include <sstream>

namespace chipflex::apps
{
template <int dim>
FluidSimulation<dim>::FluidSimulation(const sph::CaseDescription<dim>& description)
    : description_(description), fluid_(sph::build_fluid(description_))
{
}

template <int dim>
std::vector<std::string> FluidSimulation<dim>::probe_columns() const
{
  std::vector<std::string> c;
  for (const auto& p : description_.pressure_probes)
    c.push_back("p_" + p.name + "_Pa");
  for (const auto& p : description_.height_probes)
    c.push_back("h_" + p.name + "_m");
  c.push_back("lost_particles");
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
  v.push_back(double(fluid_->lost_particles().size()));
  return v;
}

template <int dim>
void FluidSimulation<dim>::save(Hdf5File& file) const
{
  fluid_->save(file, "/fluid");
}

template <int dim>
void FluidSimulation<dim>::load(const Hdf5File& file)
{
  fluid_->load(file, "/fluid");
}

template <int dim>
std::string FluidSimulation<dim>::summary() const
{
  fluid_->initialise();
  const auto& p = fluid_->parameters();
  std::ostringstream s;
  s << dim << "D SPH fluid: " << fluid_->n_fluid() << " fluid + " << fluid_->n_boundary()
    << " boundary particles, dp = " << p.particle_spacing << " m, h = " << p.smoothing_length()
    << " m, c0 = " << p.speed_of_sound << " m/s, " << fluid_->n_walls() << " wall(s)\n";
  s << "domain [" << p.domain_min.transpose() << "] - [" << p.domain_max.transpose() << "] m";
  return s.str();
}

template class FluidSimulation<2>;
template class FluidSimulation<3>;
} // namespace chipflex::apps
