#pragma once
// A case as plain data (apps/case_file.cc fills it from a ParameterHandler file; tests
// and the benchmark fill it directly) and the builder that turns it into a FluidSolver:
// fluid blocks on a lattice, a tank of walls, extra walls, derived defaults.

#include "sph/fluid_parameters.h"
#include "sph/fluid_solver.h"
#include "sph/open_boundary.h"
#include "sph/wall_surface.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace chipflex::sph
{
template <int dim>
struct FluidBlock
{
  Eigen::Matrix<double, dim, 1> min, max; ///< filled at min + (k + 1/2) dp
};

template <int dim>
struct TankDescription
{
  bool enabled = true;
  Eigen::Matrix<double, dim, 1> min, max; ///< inner faces of the walls, m
  bool open_top = true;
  /// -1, or an axis whose two faces are left open (a channel or duct: the fluid enters
  /// and leaves there through open boundaries).
  int open_axis = -1;
  WallModel model = WallModel::dummy_particles;
  int layers = 0; ///< dummy layers (0: cover the kernel support)
  LennardJonesParameters lennard_jones;
};

template <int dim>
struct Probe
{
  std::string name;
  Eigen::Matrix<double, dim, 1> position;
};

/// A 2D flow-rate gauge: the section from a to b; flow counts positive to the right of
/// a -> b (along (dy, -dx)).
/// A flow-rate gauge. 2D: the section from a to b. 3D: the whole plane through `point`
/// with unit normal `normal` (a duct's cross-section; the plane must cut the fluid only
/// where the flow is to be counted).
struct FlowSection
{
  std::string name;
  Eigen::Vector2d a, b;          ///< 2D
  Eigen::Vector3d point, normal; ///< 3D
};

template <int dim>
struct CaseDescription
{
  FluidParameters<dim> fluid;
  /// c0 = coefficient * sqrt(|g| H) with H the highest fluid block, if c0 = 0.
  double sound_coefficient = 20;
  std::vector<FluidBlock<dim>> fluid_blocks;
  TankDescription<dim> tank;
  std::vector<WallSurface<dim>> walls;
  /// Inlets and outlets; build_fluid fills their buffer boxes with the fluid's lattice
  /// (fluid-block particles inside a buffer are replaced).
  std::vector<OpenBoundary<dim>> open_boundaries;
  /// Where fluid may start: fluid-block and buffer lattice points for which it returns
  /// false are left out (a duct whose section is not a box: a closed surface of the
  /// fluid's region, e.g. a drill's flute). Empty: everywhere.
  std::function<bool(const Eigen::Matrix<double, dim, 1>&)> fluid_region;
  /// The velocity every fluid block starts with, m/s.
  Eigen::Matrix<double, dim, 1> initial_velocity = Eigen::Matrix<double, dim, 1>::Zero();
  /// Start with the hydrostatic density of each block (no initial pressure wave).
  bool hydrostatic_start = true;
  /// Domain box: if fluid.domain_min == domain_max, the bounding box of particles and
  /// walls, widened by a quarter of its size (and 4h) on every side.
  bool automatic_domain = true;
  double end_time = 1;
  double output_interval = 0.01;
  std::vector<Probe<dim>> pressure_probes; ///< Pa, Shepard-interpolated
  std::vector<Probe<dim>> height_probes;   ///< free-surface elevation on the vertical line
  std::vector<FlowSection> flow_sections;  ///< volume flow rate, 2D m^2/s, 3D m^3/s
};

/// Derives the defaults (c0, domain) into `c.fluid`, then builds the solver.
template <int dim>
std::unique_ptr<FluidSolver<dim>> build_fluid(CaseDescription<dim>& c);

/// The walls of a box tank (segments / triangles, normals into the tank).
template <int dim>
WallSurface<dim> tank_walls(const TankDescription<dim>& tank);

/// Index of the vertical axis (against gravity; the last axis without gravity).
template <int dim>
int vertical_axis(const Eigen::Matrix<double, dim, 1>& gravity);
} // namespace chipflex::sph
