// Body kind `chain`: the seed paper's rigid-link gate (1-3 links joined by torsion
// springs, Table 2 of the elastic-gate benchmark), 2D only, clamped at its top hinge
// (the body's position).

#include "apps/body_kinds/body_kind.h"
#include "coupling/multibody_coupled_body.h"
#include "mbs/composite_skin.h"
#include "mbs/rigid_chain.h"

namespace chipflex::apps
{
namespace
{
class ChainKind : public BodyKind
{
public:
  std::string name() const override { return "chain"; }
  std::string description() const override
  {
    return "chain (rigid links with torsion springs, Table 2; 2D)";
  }

  void declare(BodyKeyDeclarations& keys) const override
  {
    keys.declare("links", "1", "1|2|3", "Number of links (Table 2 of the elastic gate).");
    keys.declare("length", "0.079", "double >= 0", "Total length of the chain / strip, m.");
    keys.declare("thickness", "0.005", "double >= 0", "Thickness of the links / strip, m.");
    keys.declare("density", "1100", "double >= 0", "kg/m^3.");
    keys.declare("spring rate", "0", "double >= 0",
                 "Torsion springs, Nm/rad per metre; 0: Table 2's value.");
    keys.declare("spring damping", "0", "double >= 0", "Torsion dampers, Nms/rad per metre.");
  }

  std::unique_ptr<coupling::CoupledBody<2>> build(const BodyKeys& keys,
                                                  const BodyContext<2>& context) const override
  {
    auto gate = mbs::RigidChainGate::seed_table2(keys.integer("links"));
    gate.total_length = keys.positive("length");
    gate.thickness = keys.positive("thickness");
    gate.density = keys.positive("density");
    if (keys.number("spring rate") > 0)
      gate.spring_rate = keys.number("spring rate");
    gate.spring_damping = keys.number("spring damping");
    gate.clamp_point = context.placement.position;
    auto system = make_body_system(context);
    const mbs::RigidChain chain = mbs::add_rigid_chain(*system, gate);
    std::vector<mbs::FloatingFrameBody<2>*> links;
    for (int l : chain.links)
      links.push_back(&system->body(l));
    auto skin = std::make_unique<mbs::CompositeSkin<2>>(links);
    return std::make_unique<coupling::MultibodyCoupledBody<2>>(
        "chain", std::move(system), std::move(skin), context.max_step,
        [chain](const mbs::MultibodySystem<2>& s) { return chain.tip_position(s); });
  }

  std::unique_ptr<coupling::CoupledBody<3>> build(const BodyKeys& keys,
                                                  const BodyContext<3>&) const override
  {
    only_in_2d(name(), keys.where());
  }
};

const BodyKindRegistration registration(std::make_unique<ChainKind>());
} // namespace
} // namespace chipflex::apps
