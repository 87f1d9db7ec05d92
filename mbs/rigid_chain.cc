#include "mbs/rigid_chain.h"

#include "common/input_error.h"
#include "mbs/rigid_body.h"

namespace chipflex::mbs
{
Eigen::Vector2d RigidChain::tip_position(const MultibodySystem<2>& system) const
{
  return system.body(links.back()).point_position(Eigen::Vector2d(0.0, -link_length));
}

RigidChain add_rigid_chain(MultibodySystem<2>& system, const RigidChainSpec& spec)
{
  if (spec.n_links < 1)
    throw InputError("rigid chain", "needs at least one link, got " + std::to_string(spec.n_links));
  if (!(spec.total_length > 0 && spec.thickness > 0 && spec.density > 0 && spec.spring_rate > 0))
    throw InputError("rigid chain", "needs a positive length, thickness, density and spring rate");
  RigidChain chain;
  chain.link_length = spec.total_length / spec.n_links;
  const double l = chain.link_length;
  for (int i = 0; i < spec.n_links; ++i)
  {
    // Every link turns about its top hinge; all but the last also about the one below.
    LinkEnds ends;
    ends.round_top = spec.rounded_hinges;
    ends.round_bottom = spec.rounded_hinges && i + 1 < spec.n_links;
    auto body = make_rigid_body<2>(rectangular_link_data(l, spec.thickness, spec.density, ends));
    body->set_pose(spec.clamp_point - Eigen::Vector2d(0.0, i * l), 0.0);
    const int b = system.add_body(std::move(body));
    const int above = i == 0 ? Joint<2>::ground : chain.links.back();
    const Eigen::Vector2d hinge_above =
        i == 0 ? spec.clamp_point : Eigen::Vector2d(0.0, -l); // ground: world point
    chain.joints.push_back(system.add_joint(
        std::make_unique<RevoluteJoint<2>>(above, hinge_above, b, Eigen::Vector2d::Zero())));
    chain.springs.push_back(system.add_force_element(
        std::make_unique<TorsionSpring>(above, b, spec.spring_rate, spec.spring_damping)));
    chain.links.push_back(b);
  }
  return chain;
}
} // namespace chipflex::mbs
