#pragma once
// Gauges, as in DualSPHysics' MeasureTool: the pressure at a point is the Shepard
// interpolation sum p_j V_j W / sum V_j W over fluid neighbours (0 where dry); the water
// height on a vertical line is the highest point where the fluid's kernel fraction
// sum V_j W reaches 1/2, sampled every dp/4. The flow rate through a 2D section (3D: a
// plane) is the volume flux of the fluid in a slab two particle spacings wide around it,
// Q = (1 / 2 dp) sum_j V_j v_j . n over the particles in the slab (the slab average of
// v . n times the section's length or the plane's wetted area).
// Over MPI every rank calls them (each one sums its own particles, then the ranks add up)
// and gets the whole fluid's value.

#include "sph/fluid_solver.h"

namespace chipflex::sph
{
template <int dim>
double sample_pressure(const FluidSolver<dim>& fluid, const Eigen::Matrix<double, dim, 1>& x);

/// Elevation (coordinate along the vertical axis) of the free surface on the vertical
/// line through x; the lowest fluid elevation minus h if the line is dry.
template <int dim>
double sample_water_height(const FluidSolver<dim>& fluid, const Eigen::Matrix<double, dim, 1>& x);
/// Volume flow rate through the 2D section a -> b, m^2/s (per metre of depth), positive
/// along (dy, -dx) of a -> b.
double sample_flow_rate(const FluidSolver<2>& fluid, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b);
/// Volume flow rate through the plane through `point` with unit normal `normal`, m^3/s,
/// positive along the normal (the same slab estimate, over the whole plane).
double sample_flow_rate(const FluidSolver<3>& fluid, const Eigen::Vector3d& point,
                        const Eigen::Vector3d& normal);
} // namespace chipflex::sph
