// Body kind `fmu`: a body given as an FMI 2.0 co-simulation FMU with skin variables
// (coupling/fmu_body.h; `chipflex export fmu` writes one from a body file), coupled
// through its skin like a flexible body, 2D. Its integrator is the FMU's own; the case
// sets the FMU's parameters where it has them (clamping, pose, damping, step limit).

#include "apps/body_kinds/body_kind.h"
#include "coupling/fmu_body.h"

namespace chipflex::apps
{
namespace
{
class FmuKind : public BodyKind
{
public:
  std::string name() const override { return "fmu"; }
  std::string description() const override
  {
    return "fmu (an FMI 2.0 co-simulation FMU with skin variables; 2D)";
  }

  void declare(BodyKeyDeclarations& keys) const override
  {
    keys.declare("fmu file", "", "text",
                 "FMI 2.0 co-simulation FMU, e.g. from `chipflex export fmu`.");
    keys.declare("modal damping", "0", "double >= 0", "Damping ratio of every mode, -.");
    keys.declare("rayleigh mass", "0", "double >= 0", "Rayleigh alpha, 1/s.");
    keys.declare("rayleigh stiffness", "0", "double >= 0", "Rayleigh beta, s.");
    keys.declare("probe set", "tip", "text",
                 "Node set whose mean is the body's probe point (displacement output).");
  }

  std::unique_ptr<coupling::CoupledBody<2>> build(const BodyKeys& keys,
                                                  const BodyContext<2>& context) const override
  {
    const auto& p = context.placement;
    coupling::FmuBodySettings s;
    s.name = context.name;
    refuse_rotating_frame(name(), keys.where(), context.rotating_frame);
    s.fmu_file = keys.file("fmu file");
    s.clamped = p.clamped;
    s.position = p.position;
    s.angle = std::atan2(p.rotation(1, 0), p.rotation(0, 0));
    s.implicit = keys.flag("implicit");
    s.velocity = p.velocity;
    s.rho_infinity = context.integrator.rho_infinity;
    s.max_step = context.max_step;
    s.modal_damping = keys.number("modal damping");
    s.rayleigh_mass = keys.number("rayleigh mass");
    s.rayleigh_stiffness = keys.number("rayleigh stiffness");
    s.probe_set = keys.text("probe set");
    return coupling::make_fmu_body(s, context.gravity);
  }

  std::unique_ptr<coupling::CoupledBody<3>> build(const BodyKeys& keys,
                                                  const BodyContext<3>&) const override
  {
    only_in_2d(name(), keys.where());
  }
};

const BodyKindRegistration registration(std::make_unique<FmuKind>());
} // namespace
} // namespace chipflex::apps
