#pragma once
// A rigid chain: n equal rectangular links hanging from a clamp, joined by revolute
// joints with linear torsion springs (the first one between the clamp and link 0).
// Planar, per metre of depth. The elastic gate's rigid-chain models (1, 2 or 3 links,
// Table 2 of its benchmark) are such chains; their values live in its case files.

#include "mbs/multibody_system.h"

#include <Eigen/Dense>
#include <vector>

namespace chipflex::mbs
{
struct RigidChainSpec
{
  int n_links = 1;
  double total_length = 0;   ///< m, clamp to free end
  double thickness = 0;      ///< m
  double density = 0;        ///< kg/m^3
  double spring_rate = 0;    ///< Nm/rad per metre of depth, at every joint
  double spring_damping = 0; ///< Nms/rad per metre of depth
  Eigen::Vector2d clamp_point = Eigen::Vector2d::Zero(); ///< top hinge in the world
  /// Round the links' hinge ends (LinkEnds), so that no gap opens at a joint as it turns.
  bool rounded_hinges = true;
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
/// InputError unless n_links >= 1 and length, thickness, density and spring rate > 0.
RigidChain add_rigid_chain(MultibodySystem<2>& system, const RigidChainSpec& spec);
} // namespace chipflex::mbs
