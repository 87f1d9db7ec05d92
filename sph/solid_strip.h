#pragma once
// A 2D strip (beam) of SPH solid particles clamped at one end, with the skin the fluid
// sees: the seed paper's SPH gate (Table 1 in docs/elastic_gate.md: six particle layers across
// the thickness, a clamp of 8 x 4 fixed particles).
//
// Why a skin: the fluid never interacts with solid particles directly; it feels a
// polyline around the strip (coupling/ makes it a moving wall). A skin node sits half
// a spacing outside a boundary particle, x_node = x_p + 1/2 sum_q (x_p - x_q) over its
// inward lattice neighbours q, i.e. x_node = sum_k w_k x_k with sum_k w_k = 1. Its
// velocity uses the same weights and a force on it is spread with the same weights
// (the transpose), so momentum and power pass unchanged between fluid and solid.

#include "sph/solid_body.h"

#include <array>
#include <limits>
#include <utility>
#include <vector>

namespace chipflex::sph
{
struct SolidStripLayout
{
  Eigen::Vector2d clamped_end_centre = Eigen::Vector2d::Zero(); ///< m
  Eigen::Vector2d direction = Eigen::Vector2d(0, -1);           ///< unit, clamped end -> free end
  /// The strip's size, m: no defaults (NaN), every strip states its own.
  double length = std::numeric_limits<double>::quiet_NaN();
  double thickness = std::numeric_limits<double>::quiet_NaN();
  double spacing = 1e-3; ///< m, along the length
  int layers = 6;        ///< particles across the thickness
  int clamp_rows = 4;    ///< fixed rows beyond the clamped end
  int clamp_columns = 8; ///< fixed particles per clamp row (>= layers, centred)
};

struct SolidSkin
{
  /// Per skin node: (particle, weight) pairs, weights summing to one.
  std::vector<std::vector<std::pair<int, double>>> nodes;
  /// Consecutive skin nodes, traversed so that (dy, -dx) points out of the strip.
  std::vector<std::array<int, 2>> faces;
  /// Skin nodes on the free end; their mean is the free-end probe.
  std::vector<int> tip_nodes;
};

/// Adds the strip's particles (deformable, then clamp) to `solid` and returns its
/// skin: the two long sides and the free end (the clamped end sits inside the clamp).
SolidSkin build_solid_strip(SolidBody<2>& solid, const SolidStripLayout& layout);
} // namespace chipflex::sph
