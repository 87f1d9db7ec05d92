#pragma once
// The seed paper's rigid-chain models of the elastic gate (docs/elastic_gate.md, Table 2:
// 1, 2 or 3 links, spring rates 3.95, 3.95, 2.633 Nm per metre of depth): n equal
// rectangular rubber links hanging from a clamp, joined by revolute joints with linear
// torsion springs (the first one between the clamp and link 0). Planar, per metre depth.

#include "mbs/multibody_system.h"

#include <Eigen/Dense>
#include <vector>

namespace chipflex::mbs
{
struct RigidChainGate
{
  int n_links = 1;
  double total_length = 0.079; ///< m, clamp to free end
  double thickness = 0.005;    ///< m
  double density = 1100;       ///< kg/m^3 (rubber)
  double spring_rate = 3.95;   ///< Nm/rad per metre of depth, at every joint
  double spring_damping = 0;   ///< Nms/rad per metre of depth
  Eigen::Vector2d clamp_point = Eigen::Vector2d::Zero(); ///< top hinge in the world
  /// Round the links' hinge ends (LinkEnds), so that no gap opens at a joint as it turns.
  bool rounded_hinges = true;

  /// Table 2 of the seed paper: 1 link 79 mm 3.95 Nm; 2 links 39.5 mm 3.95 Nm;
  /// 3 links 26.33 mm 2.633 Nm. InputError for other n.
  static RigidChainGate seed_table2(int n_links);
};

/// Indices of what add_rigid_chain put into the system.
struct RigidChain
{
  std::vector<int> links;   ///< bodies, from the clamp down
  std::vector<int> joints;  ///< revolute joints, joint 0 at the clamp
  std::vector<int> springs; ///< force elements, spring i across joint i
  double link_length = 0;
  /// World position of the free end (middle of the last link's bottom edge).
  Eigen::Vector2d tip_position(const MultibodySystem<2>& system) const;
};

/// Adds the links hanging straight down (frame origin of link i at clamp - (0, i L)).
RigidChain add_rigid_chain(MultibodySystem<2>& system, const RigidChainGate& gate);
} // namespace chipflex::mbs
