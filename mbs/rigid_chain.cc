#include "mbs/rigid_chain.h"

#include "common/input_error.h"
#include "mbs/rigid_body.h"

namespace chipflex::mbs
{
RigidChainGate RigidChainGate::seed_table2(int n_links)
{
  RigidChainGate g;
  g.n_links = n_links;
  switch (n_links)
  {
  case 1:
  case 2:
    g.spring_rate = 3.95;
    break;
  case 3:
    g.spring_rate = 2.633;
    break;
  default:
    throw InputError("rigid chain gate", "the seed paper's Table 2 has 1, 2 or 3 links, not " +
                                             std::to_string(n_links));
  }
  return g;
}

Eigen::Vector2d RigidChain::tip_position(const MultibodySystem<2>& system) const
{
  return system.body(links.back()).point_position(Eigen::Vector2d(0.0, -link_length));
}

RigidChain add_rigid_chain(MultibodySystem<2>& system, const RigidChainGate& gate)
{
  if (gate.n_links < 1 || gate.total_length <= 0)
    throw InputError("rigid chain gate", "needs at least one link and a positive length");
  RigidChain chain;
  chain.link_length = gate.total_length / gate.n_links;
  const double l = chain.link_length;
  for (int i = 0; i < gate.n_links; ++i)
  {
    // Every link turns about its top hinge; all but the last also about the one below.
    LinkEnds ends;
    ends.round_top = gate.rounded_hinges;
    ends.round_bottom = gate.rounded_hinges && i + 1 < gate.n_links;
    auto body = make_rigid_body<2>(rectangular_link_data(l, gate.thickness, gate.density, ends));
    body->set_pose(gate.clamp_point - Eigen::Vector2d(0.0, i * l), 0.0);
    const int b = system.add_body(std::move(body));
    const int above = i == 0 ? Joint<2>::ground : chain.links.back();
    const Eigen::Vector2d hinge_above =
        i == 0 ? gate.clamp_point : Eigen::Vector2d(0.0, -l); // ground: world point
    chain.joints.push_back(system.add_joint(
        std::make_unique<RevoluteJoint<2>>(above, hinge_above, b, Eigen::Vector2d::Zero())));
    chain.springs.push_back(system.add_force_element(
        std::make_unique<TorsionSpring>(above, b, gate.spring_rate, gate.spring_damping)));
    chain.links.push_back(b);
  }
  return chain;
}
} // namespace chipflex::mbs
