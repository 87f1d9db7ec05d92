#include "coupling/sph_solid_body.h"

#include <stdexcept>

namespace chipflex::coupling
{
SphSolidBody::SphSolidBody(const sph::SolidMaterial& material, const sph::SolidStripLayout& layout,
                           double smoothing_factor, const Vector& gravity)
    : solid_(material, layout.spacing, smoothing_factor * layout.spacing)
{
  skin_map_ = sph::build_solid_strip(solid_, layout);
  solid_.set_gravity(gravity);
}

void SphSolidBody::combine(const std::vector<Vector>& particle_values,
                           std::vector<Vector>& out) const
{
  out.assign(skin_map_.nodes.size(), Vector::Zero());
  for (std::size_t k = 0; k < skin_map_.nodes.size(); ++k)
    for (const auto& [p, w] : skin_map_.nodes[k])
      out[k] += w * particle_values[p];
}

void SphSolidBody::skin_positions(std::vector<Vector>& x) const
{
  combine(solid_.positions(), x);
}

void SphSolidBody::skin_velocities(std::vector<Vector>& v) const
{
  combine(solid_.velocities(), v);
}

void SphSolidBody::set_skin_forces(const std::vector<Vector>& f)
{
  if (f.size() != skin_map_.nodes.size())
    throw std::logic_error("SphSolidBody: one force per skin node expected");
  std::vector<Vector> particle_forces(solid_.n_particles(), Vector::Zero());
  for (std::size_t k = 0; k < f.size(); ++k)
    for (const auto& [p, w] : skin_map_.nodes[k])
      particle_forces[p] += w * f[k];
  solid_.set_external_forces(particle_forces);
}

double SphSolidBody::contact_lead(double dt) const
{
  const int n = std::max(1, static_cast<int>(std::ceil(dt / solid_.stable_time_step() - 1e-9)));
  return (n - 1) / (2.0 * n);
}

double SphSolidBody::mass() const
{
  double m = 0;
  for (double mi : solid_.masses())
    m += mi;
  return m;
}

SphSolidBody::Vector SphSolidBody::probe_position() const
{
  std::vector<Vector> x;
  skin_positions(x);
  Vector sum = Vector::Zero();
  for (int k : skin_map_.tip_nodes)
    sum += x[k];
  return sum / static_cast<double>(skin_map_.tip_nodes.size());
}

void SphSolidBody::advance(double dt)
{
  substeps_ += solid_.advance(dt);
}
} // namespace chipflex::coupling
