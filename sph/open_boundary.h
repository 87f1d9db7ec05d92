#pragma once
// Open flow boundaries: inlet and outlet buffer zones (after DualSPHysics' inlet/outlet,
// Tafuni, Dominguez, Vacondio & Crespo, CMAME 342 (2018) 604-624).
//
// A zone is a box of buffer particles beside the fluid, `thickness` deep along its flow
// axis; its face on the fluid side is the boundary plane. Buffer particles are fluid
// particles whose state is prescribed instead of integrated, so the fluid next to the
// plane has a full kernel support:
//   inlet   velocity prescribed (a mean normal speed, uniform or parabolic across the
//           section, optionally ramped up), density extrapolated from the fluid;
//   outlet  pressure prescribed (density from the equation of state, hydrostatic when
//           there is gravity), velocity extrapolated from the fluid.
// A buffer particle moves with its prescribed velocity. An inlet particle that crosses
// the plane becomes fluid and a new buffer particle takes its place one buffer thickness
// upstream (the buffer stays full, the lattice rows continue); a fluid particle that
// crosses an outlet plane becomes a buffer particle, and is removed (outflow) when it
// leaves the buffer's far face. The extrapolation (sph/fluid_solver_open_boundaries.cc)
// takes the fluid's value at the buffer particle's mirror point across the plane from a
// first-order moving-least-squares fit (Tafuni et al.'s ghost nodes); the density adds
// the fitted gradient times the distance back to the buffer particle.
//
// Zones are axis-aligned (flow along +-x, +-y or +-z) and live wholly inside the
// domain box. This header holds the description and its geometry; FluidSolver owns the
// zones' particles.

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

namespace chipflex::sph
{
enum class OpenBoundaryKind
{
  inlet,
  outlet
};

enum class InletProfile
{
  uniform,  ///< the same speed across the section
  parabolic ///< 2D: 1.5 U (1 - eta^2) (plane Poiseuille); 3D: 2.25 U (1 - eta1^2)(1 - eta2^2)
};

template <int dim>
struct OpenBoundary
{
  using Vector = Eigen::Matrix<double, dim, 1>;

  std::string name = "inlet";
  OpenBoundaryKind kind = OpenBoundaryKind::inlet;
  /// The buffer box, m. Its face on the fluid side is the boundary plane; its depth along
  /// the flow axis (the buffer layers times dp) must cover the kernel support 2h.
  Vector box_min = Vector::Zero(), box_max = Vector::Zero();
  int axis = 0; ///< flow axis (0 x, 1 y, 2 z)
  int sign = 1; ///< +1: the flow runs along +axis, -1: along -axis
  /// Inlet: mean normal speed over the section, m/s (> 0: into the fluid).
  double velocity = 0;
  /// Inlet: a volume flow rate instead, m^3/s (2D: m^2/s per metre of depth); > 0 sets
  /// `velocity` when the fluid is built (sph/case_setup.cc): flow rate over the section
  /// the buffer's fluid fills (its lattice points times dp^dim over the buffer's depth),
  /// so a buffer box larger than a shaped section (geometry/fluid region) still gets the
  /// rate. A parabolic profile takes the box's section.
  double flow_rate = 0;
  InletProfile profile = InletProfile::uniform;
  /// Inlet: the speed rises as (1 - cos(pi t / T)) / 2 over [0, T], s (0: at once).
  double ramp_time = 0;
  /// Outlet: pressure at the centre of the section, Pa (gauge, as the Tait law).
  double pressure = 0;

  double thickness() const { return box_max[axis] - box_min[axis]; }
  /// Coordinate of the boundary plane along the flow axis.
  double plane() const
  {
    const bool upper = (kind == OpenBoundaryKind::inlet) == (sign > 0);
    return upper ? box_max[axis] : box_min[axis];
  }
  /// Distance from the plane into the buffer (0 at the plane, thickness() at the far
  /// face); negative on the fluid side.
  double depth(const double* x) const
  {
    const double s = kind == OpenBoundaryKind::inlet ? plane() - x[axis] : x[axis] - plane();
    return s * sign;
  }
  /// Inside the section (the box's extent across the flow axis).
  bool in_section(const double* x) const
  {
    bool in = true;
    for (int d = 0; d < dim; ++d)
      in = in && (d == axis || (x[d] >= box_min[d] && x[d] <= box_max[d]));
    return in;
  }
  /// Unit vector pointing from the plane into the fluid.
  Vector into_fluid() const
  {
    Vector n = Vector::Zero();
    n[axis] = kind == OpenBoundaryKind::inlet ? sign : -sign;
    return n;
  }
  /// Section area (2D: width, m; 3D: m^2).
  double section_area() const
  {
    double a = 1;
    for (int d = 0; d < dim; ++d)
      if (d != axis)
        a *= box_max[d] - box_min[d];
    return a;
  }
  /// Inlet: the prescribed normal speed at x and time t, m/s.
  double speed(const double* x, double t) const
  {
    double u = velocity;
    if (profile == InletProfile::parabolic)
      for (int d = 0; d < dim; ++d)
        if (d != axis)
        {
          const double eta = (2 * x[d] - box_min[d] - box_max[d]) / (box_max[d] - box_min[d]);
          u *= 1.5 * (1 - eta * eta);
        }
    if (ramp_time > 0 && t < ramp_time)
      u *= 0.5 * (1 - std::cos(M_PI * t / ramp_time));
    return u;
  }
};

/// The flow through one zone so far (FluidSolver::open_boundary_flow).
struct OpenBoundaryFlow
{
  std::int64_t created = 0; ///< particles created (inlet)
  std::int64_t removed = 0; ///< particles removed through the zone (outflow)
  /// Mass flow through the buffer now: m / thickness * sum of the buffer particles'
  /// speeds along the flow direction (the slab average of rho u), kg/s (2D: per metre).
  double mass_flow = 0;
  std::size_t buffer_particles = 0;
};
} // namespace chipflex::sph
