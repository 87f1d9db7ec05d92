// Body kind `chain`: equal rigid links joined by torsion springs, hanging from a clamp
// hinge at the body's position, 2D only (mbs/rigid_chain.h). The elastic gate's chain
// variants (cases/elastic_gate/chain*.prm) give it their Table 2 values.

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
    return "chain (rigid links with torsion springs; 2D)";
  }

  void declare(BodyKeyDeclarations& keys) const override
  {
    keys.declare("links", "1", "integer >= 1", "Number of equal links.");
    keys.declare("length", "0", "double >= 0", "Total length of the chain / strip, m (required).");
    keys.declare("thickness", "0", "double >= 0", "Thickness of the links / strip, m (required).");
    keys.declare("density", "", "text", "kg/m^3 (required: no default).");
    keys.declare("spring rate", "0", "double >= 0",
                 "Torsion spring at every joint, Nm/rad per metre of depth (required).");
    keys.declare("spring damping", "0", "double >= 0", "Torsion dampers, Nms/rad per metre.");
  }

  std::unique_ptr<coupling::CoupledBody<2>> build(const BodyKeys& keys,
                                                  const BodyContext<2>& context) const override
  {
    mbs::RigidChainSpec gate;
    gate.n_links = keys.integer("links");
    gate.total_length = keys.positive("length");
    gate.thickness = keys.positive("thickness");
    gate.density = keys.positive("density");
    gate.spring_rate = keys.positive("spring rate");
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
