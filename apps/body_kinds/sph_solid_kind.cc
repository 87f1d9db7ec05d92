// Body kind `sph solid`: an elastic strip of SPH solid particles, clamped at one end, 2D
// only: total-Lagrangian St Venant-Kirchhoff with corrected kernel gradients (Bonet & Lok
// 1999) by default, or the seed's Gray, Monaghan & Swift 2001 solid. Density, E and nu
// have no defaults: every body states its material.

#include "apps/body_kinds/body_kind.h"
#include "common/input_error.h"
#include "coupling/sph_solid_body.h"

namespace chipflex::apps
{
namespace
{
class SphSolidKind : public BodyKind
{
public:
  std::string name() const override { return "sph solid"; }
  std::string description() const override
  {
    return "sph solid (SPH strip clamped at one end, total Lagrangian or Gray et al. 2001; 2D)";
  }

  void declare(BodyKeyDeclarations& keys) const override
  {
    keys.declare("length", "0", "double >= 0", "Total length of the chain / strip, m (required).");
    keys.declare("thickness", "0", "double >= 0", "Thickness of the links / strip, m (required).");
    keys.declare("density", "", "text", "kg/m^3 (required: no default).");
    keys.declare("youngs modulus", "", "text", "E, Pa (required: no default).");
    keys.declare("poisson ratio", "", "text", "nu, -, -1 < nu < 0.5 (required: no default).");
    keys.declare("artificial stress", "0.2", "double >= 0",
                 "epsilon (Table 1); updated Lagrangian only.");
    keys.declare("solid viscosity", "1", "double >= 0", "Monaghan alpha, -.");
    keys.declare("spacing", "0.001", "double >= 0", "Particle spacing along the strip, m.");
    keys.declare("layers", "6", "integer >= 2", "Particles across the thickness.");
    keys.declare("clamp rows", "4", "integer >= 1", "Fixed rows beyond the clamp.");
    keys.declare("clamp columns", "8", "integer >= 2", "Fixed particles per row.");
    keys.declare("smoothing factor", "1.3", "double >= 0", "h / spacing, -.");
    keys.declare("direction", "0, -1", "text", "Unit vector from the clamped to the free end.");
    keys.declare("formulation", "total lagrangian", "total lagrangian|updated lagrangian",
                 "total lagrangian: St Venant-Kirchhoff on reference neighbours (Bonet & Lok "
                 "1999); updated lagrangian: the seed's Gray et al. 2001 solid (docs/sph.md).");
    keys.declare("kernel gradient correction", "true", "bool",
                 "Bonet & Lok (1999) corrected kernel gradients (docs/sph.md).");
    keys.declare("hourglass control", "10", "double >= 0",
                 "Total Lagrangian: Ganzenmueller (2015) hourglass coefficient alpha, -; 0: off.");
  }

  std::unique_ptr<coupling::CoupledBody<2>> build(const BodyKeys& keys,
                                                  const BodyContext<2>& context) const override
  {
    sph::SolidMaterial material;
    material.density = keys.positive("density");
    material.youngs_modulus = keys.positive("youngs modulus");
    material.poisson_ratio = keys.number("poisson ratio");
    if (!(material.poisson_ratio > -1 && material.poisson_ratio < 0.5))
      throw InputError(keys.at("poisson ratio"),
                       "must lie in (-1, 0.5), got " + keys.text("poisson ratio"));
    material.artificial_stress = keys.number("artificial stress");
    material.viscosity_alpha = keys.number("solid viscosity");
    material.kernel_gradient_correction = keys.flag("kernel gradient correction");
    material.hourglass_control = keys.number("hourglass control");
    material.formulation = keys.text("formulation") == "updated lagrangian"
                               ? sph::SolidFormulation::updated_lagrangian
                               : sph::SolidFormulation::total_lagrangian;
    refuse_rotating_frame(name(), keys.where(), context.rotating_frame);
    sph::SolidStripLayout layout;
    layout.clamped_end_centre = context.placement.position;
    layout.direction = keys.vector<2>("direction");
    if (!(layout.direction.norm() > 0))
      throw InputError(keys.at("direction"), "must not be the zero vector");
    layout.length = keys.positive("length");
    layout.thickness = keys.positive("thickness");
    layout.spacing = keys.positive("spacing");
    layout.layers = keys.integer("layers");
    layout.clamp_rows = keys.integer("clamp rows");
    layout.clamp_columns = keys.integer("clamp columns");
    if (layout.clamp_columns < layout.layers)
      throw InputError(keys.at("clamp columns"), "the clamp must be at least as wide as the strip");
    return std::make_unique<coupling::SphSolidBody>(
        material, layout, keys.positive("smoothing factor"), context.gravity);
  }

  std::unique_ptr<coupling::CoupledBody<3>> build(const BodyKeys& keys,
                                                  const BodyContext<3>&) const override
  {
    only_in_2d(name(), keys.where());
  }
};

const BodyKindRegistration registration(std::make_unique<SphSolidKind>());
} // namespace
} // namespace chipflex::apps
