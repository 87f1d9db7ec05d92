#pragma once
// An SPH solid (sph::SolidBody) as a coupled body: its
// skin nodes are fixed linear combinations of particle positions (sph/solid_strip.h),
// so their velocities use the same weights and skin forces are spread back to the
// particles with them — the transpose map that conserves momentum and power. The solid
// sub-steps at its own (much smaller) stable step within each fluid step.

#include "coupling/coupled_body.h"
#include "sph/solid_body.h"
#include "sph/solid_strip.h"

namespace chipflex::coupling
{
class SphSolidBody : public CoupledBody<2>, public mbs::SkinBody<2>
{
public:
  using Vector = Eigen::Vector2d;

  SphSolidBody(const sph::SolidMaterial& material, const sph::SolidStripLayout& layout,
               double smoothing_factor, const Vector& gravity);

  // CoupledBody
  std::string kind() const override { return "sph-solid"; }
  mbs::SkinBody<2>& skin() override { return *this; }
  void advance(double dt) override;
  Vector linear_momentum() const override { return solid_.linear_momentum(); }
  double mass() const override;
  /// Symplectic Euler in n = ceil(dt / stable step) sub-steps: (n - 1) / 2n.
  double contact_lead(double dt) const override;
  Vector probe_position() const override;
  std::vector<double> state() const override { return solid_.state(); }
  void restore(const std::vector<double>& state) override { solid_.restore(state); }

  // SkinBody
  std::size_t n_skin_nodes() const override { return skin_map_.nodes.size(); }
  const std::vector<std::array<int, 2>>& skin_faces() const override { return skin_map_.faces; }
  void skin_positions(std::vector<Vector>& x) const override;
  void skin_velocities(std::vector<Vector>& v) const override;
  void set_skin_forces(const std::vector<Vector>& f) override;

  const sph::SolidBody<2>& solid() const { return solid_; }
  const sph::SolidSkin& skin_map() const { return skin_map_; }
  long substeps() const { return substeps_; }

private:
  void combine(const std::vector<Vector>& particle_values, std::vector<Vector>& out) const;

  sph::SolidBody<2> solid_;
  sph::SolidSkin skin_map_;
  long substeps_ = 0;
};
} // namespace chipflex::coupling
