#pragma once
// Small cases shared by the sph tests (coarse resolutions keep them fast).

#include "sph/case_setup.h"

namespace chipflex::sph::testing
{
/// A water column of width W and height H at rest in a W-wide open tank.
inline CaseDescription<2> water_column(double width, double height, double dp,
                                       WallModel model = WallModel::dummy_particles)
{
  CaseDescription<2> c;
  c.fluid.particle_spacing = dp;
  c.fluid.gravity = Eigen::Vector2d(0, -9.81);
  c.sound_coefficient = 10;
  c.fluid_blocks.push_back({Eigen::Vector2d(0, 0), Eigen::Vector2d(width, height)});
  c.tank.min = Eigen::Vector2d(0, 0);
  c.tank.max = Eigen::Vector2d(width, 1.5 * height);
  c.tank.model = model;
  return c;
}

/// A closed box without gravity, Lennard-Jones walls, fluid filling part of it.
inline CaseDescription<2> closed_box(double dp)
{
  CaseDescription<2> c;
  c.fluid.particle_spacing = dp;
  c.fluid.gravity = Eigen::Vector2d::Zero();
  c.fluid.speed_of_sound = 20;
  c.fluid.scheme = TimeScheme::symplectic;
  c.fluid.density_diffusion = DensityDiffusionModel::molteni_colagrossi;
  c.fluid_blocks.push_back({Eigen::Vector2d(0, 0), Eigen::Vector2d(0.3, 0.2)});
  c.tank.min = Eigen::Vector2d(0, 0);
  c.tank.max = Eigen::Vector2d(0.4, 0.4);
  c.tank.open_top = false;
  c.tank.model = WallModel::lennard_jones;
  c.hydrostatic_start = false;
  return c;
}
} // namespace chipflex::sph::testing
