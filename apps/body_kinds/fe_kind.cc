// Body kind `fe`: the full geometrically nonlinear FE model of a mesh (fem/fe_body_model.h:
// total Lagrangian, St Venant-Kirchhoff or neo-Hooke, generalised-alpha with Newton), 2D or
// 3D, clamped on a boundary group or free, coupled through its skin nodes by
// coupling/subcycled_nodal_body.h (one FE step per fluid step, or the fluid sub-cycling
// inside FE steps of `fe time step`). The reference against which a reduced body is judged
// in the flow.

#include "apps/body_kinds/body_kind.h"
#include "common/input_error.h"
#include "coupling/subcycled_nodal_body.h"
#include "fem/fe_body_model.h"

#include <algorithm>
#include <cmath>

namespace chipflex::apps
{
namespace
{
class FeKind : public AnyDimensionKind<FeKind>
{
public:
  std::string name() const override { return "fe"; }
  std::string description() const override
  {
    return "fe (the full geometrically nonlinear FE model of a mesh)";
  }

  void declare(BodyKeyDeclarations& keys) const override
  {
    keys.declare("mesh", "", "text",
                 "gmsh .msh (rigid: a closed surface mesh; fe: the body's mesh, as for "
                 "`chipflex reduce`).");
    keys.declare("clamp group", "clamp", "text",
                 "fe, clamped: the boundary group held fixed (as `reduce --clamp`).");
    keys.declare("density", "", "text", "kg/m^3 (required: no default).");
    keys.declare("youngs modulus", "", "text", "E, Pa (required: no default).");
    keys.declare("poisson ratio", "", "text", "nu, -, -1 < nu < 0.5 (required: no default).");
    keys.declare("plane stress", "false", "bool",
                 "fe, 2D: plane stress instead of plane strain (svk only).");
    keys.declare("material model", "svk", "svk|neo-hooke",
                 "fe: St Venant-Kirchhoff or compressible neo-Hooke.");
    keys.declare("degree", "2", "1|2", "fe: element degree.");
    keys.declare("fe time step", "0", "double >= 0",
                 "fe: the FE model's own time step, s, the fluid sub-cycling within it; 0: one "
                 "FE step per fluid step.");
    keys.declare("rayleigh mass", "0", "double >= 0", "Rayleigh alpha, 1/s.");
    keys.declare("rayleigh stiffness", "0", "double >= 0", "Rayleigh beta, s.");
    keys.declare("probe set", "tip", "text",
                 "Node set whose mean is the body's probe point (displacement output).");
  }

  template <int dim>
  static std::unique_ptr<coupling::CoupledBody<dim>> make(const BodyKeys& keys,
                                                          const BodyContext<dim>& context)
  {
    fem::FeBodySettings s;
    s.mesh_file = keys.file("mesh");
    s.material.youngs_modulus = keys.positive("youngs modulus");
    s.material.density = keys.positive("density");
    s.material.poisson_ratio = keys.number("poisson ratio");
    if (!(s.material.poisson_ratio > -1 && s.material.poisson_ratio < 0.5))
      throw InputError(keys.at("poisson ratio"), "must lie in (-1, 0.5)");
    s.material.plane_stress = keys.flag("plane stress");
    if (dim == 3 && s.material.plane_stress)
      throw InputError(keys.at("plane stress"), "is for 2D bodies");
    s.model = fem::parse_hyperelastic_model(keys.text("material model"), keys.at("material model"));
    if (s.material.plane_stress && s.model == fem::HyperelasticModel::neo_hooke)
      throw InputError(keys.at("plane stress"), "exists with material model = svk only");
    s.degree = keys.integer("degree");
    if (context.placement.clamped)
    {
      s.clamp_group = keys.text("clamp group");
      if (s.clamp_group.empty())
        throw InputError(keys.at("clamp group"), "a clamped fe body needs a clamp group");
    }
    if (context.integrator.scheme != mbs::IntegratorOptions::Scheme::generalized_alpha)
      throw InputError(keys.where() + ", implicit",
                       "an fe body is integrated implicitly (generalised-alpha)");
    s.rho_infinity = context.integrator.rho_infinity;
    s.rayleigh_mass = keys.number("rayleigh mass");
    s.rayleigh_stiffness = keys.number("rayleigh stiffness");
    if (context.placement.velocity.norm() > 0 || context.placement.angular_velocity.norm() > 0)
      throw InputError(keys.where() + ", velocity", "an fe body starts at rest");
    refuse_rotating_frame("fe", keys.where(), context.rotating_frame);
    const double fe_step = keys.number("fe time step");
    if (fe_step > 0 && context.max_step > 0)
      throw InputError(keys.at("fe time step"), "give either fe time step or max step, not both");

    auto model = std::make_unique<fem::FeBodyModel<dim>>(s);
    const std::string probe_set = keys.text("probe set");
    std::vector<int> probe;
    if (model->has_node_set(probe_set))
      probe = model->node_set(probe_set);
    else if (probe_set != "tip")  // the default may be missing: the frame origin then
      model->node_set(probe_set); // InputError naming the missing group
    return std::make_unique<coupling::SubcycledNodalBody<dim, fem::FeBodyModel<dim>>>(
        "fe", std::move(model), context.placement.rotation, context.placement.position,
        context.gravity, fe_step, context.max_step, std::move(probe));
  }
};

const BodyKindRegistration registration(std::make_unique<FeKind>());
} // namespace
} // namespace chipflex::apps
