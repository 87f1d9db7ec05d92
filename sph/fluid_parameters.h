#pragma once
// Every physical and numerical choice of the weakly-compressible SPH fluid, as a plain
// struct: apps/case_file.cc fills it from the case file (where each key is documented
// with its unit and default), tests and benchmarks fill it directly.

#include "common/rotating_frame.h"

#include <Eigen/Core>
#include <limits>

namespace chipflex::sph
{
enum class ViscosityModel
{
  artificial, ///< Monaghan (1992) artificial viscosity, coefficient alpha
  laminar     ///< Lo & Shao (2002) laminar viscosity, kinematic viscosity nu
};

enum class DensityDiffusionModel
{
  none,
  molteni_colagrossi, ///< Molteni & Colagrossi (2009) delta-SPH term
  fourtakas           ///< Fourtakas et al. (2019): the same term on the dynamic density
};

enum class TimeScheme
{
  verlet,     ///< Verlet with an Euler step every `verlet_euler_every` steps (DualSPHysics)
  symplectic, ///< Monaghan's symplectic position-Verlet predictor-corrector (DualSPHysics):
              ///< forces at t_n for the predictor and at t_n+1/2 for the corrector
  /// The same drift-kick-drift step with ONE force pass: the predictor's velocity and
  /// density rates are the previous step's mid-step ones. The mid-step positions do not
  /// depend on them (x_n + dt/2 v_n), so only the velocity-dependent terms (viscosity,
  /// continuity) see an O(dt) older rate; the momentum update v_n+1 = v_n + dt a_n+1/2 is
  /// unchanged, and so is the exactness of the coupling's momentum exchange.
  position_verlet
};

/// The symplectic family keeps x_n and v_n beside the mid-step state.
inline bool is_symplectic(TimeScheme s)
{
  return s == TimeScheme::symplectic || s == TimeScheme::position_verlet;
}

/// Kernel-support filling (particles in the support over those of a full lattice
/// support, sph/force_loop.h) below which a fluid particle is spray. With h = sqrt(dim) dp
/// a pair has 2/21 (3D: 2/171) however close, a flat free surface 0.62, a right-angled
/// edge 0.38, the fluid 1.
inline constexpr double spray_fill_threshold = 0.4;

/// The coefficient A of particle shifting's D = A h |v| dt where a case switches it on
/// (DualSPHysics' shifting coefficient -2).
inline constexpr double default_shifting_coefficient = 2;

template <int dim>
struct FluidParameters
{
  using Vector = Eigen::Matrix<double, dim, 1>;

  double particle_spacing = 0.01; ///< dp, m
  /// Smoothing length h = coefficient * sqrt(dim) * dp (DualSPHysics' coefh: 1 gives
  /// h = 0.014142 m for dp = 0.01 m in 2D). The kernel support is 2h.
  double smoothing_coefficient = 1.0;
  double reference_density = 1000; ///< rho0, kg/m^3
  double speed_of_sound = 0;       ///< c0, m/s (0: derived by the case builder)
  double gamma = 7;                ///< Tait exponent
  Vector gravity = Vector::Zero(); ///< m/s^2
  /// The frame the case is written in may turn (the drill's frame): every fluid particle
  /// then feels its centrifugal, Coriolis and Euler accelerations. Inactive by default.
  RotatingFrame rotating_frame;
  ViscosityModel viscosity = ViscosityModel::artificial;
  double artificial_viscosity = 0.02; ///< alpha (-)
  double kinematic_viscosity = 1e-6;  ///< nu, m^2/s (laminar model)
  DensityDiffusionModel density_diffusion = DensityDiffusionModel::fourtakas;
  double density_diffusion_delta = 0.1; ///< delta (-)
  /// Spray (a fluid particle whose kernel support is less than spray_fill_threshold
  /// filled, sph/force_loop.h) gets p = max(p_Tait, 0). With the plain Tait law a
  /// detached pair of particles below rho0 attracts, binds, orbits (its density
  /// drifting) and flies apart at several times c0. The fluid proper keeps its tension:
  /// cut there too, stretched water under a jet thins to a tenth of rho0 and blows up.
  /// Off by default: the filling counts particles only, so fluid in a corner of
  /// Lennard-Jones walls (which have none) counts as spray; in the closed Lennard-Jones box
  /// of tests/sph/test_conservation.cc one such particle then passes the wall and is
  /// removed, and the moving Lennard-Jones piston is pulled instead of pushed.
  bool cut_spray_tension = false;
  /// Pressure floor, Pa (<= 0; -infinity: none, the plain Tait law). Water at a free
  /// surface cannot hold the tension a stretched SPH particle pair builds (air enters):
  /// with p >= p_min a pair that snaps apart gains at most sqrt(2 |p_min| / rho0). At
  /// p_min = -rho0 g H that is sqrt(2 g H), the speed the flow itself can reach, so
  /// stretched particles are not catapulted while the fluid keeps the small tension its
  /// free surface needs (docs/sph.md, "Stray particles and spray").
  double minimum_pressure = -std::numeric_limits<double>::infinity();
  /// Background (ambient) pressure, Pa (>= 0), added to every particle's equation-of-state
  /// pressure in the momentum equation only. A uniform addition exerts no force where the
  /// kernel support is full (inside the fluid, at dummy-particle walls and thin skins,
  /// which carry it too), so the fluid starts in equilibrium with it; where a wake's
  /// suction would stretch the fluid into tension, the particles keep pushing each other
  /// apart and the flow stays whole (Adami, Hu & Adams 2013; Marrone et al. 2013). The
  /// gauges, outputs, open boundaries and the pressure floor stay gauge (relative to it).
  /// For internal flows: at a free surface or a Lennard-Jones wall the support is
  /// truncated and the background pressure pushes the fluid outwards or into the wall.
  double background_pressure = 0;
  /// Each force pass moves the fluid's density this fraction of the way from its
  /// continuity value to the kernel sum rho0 sum_j W_ij / sum_lattice W (0: the continuity
  /// equation alone; sph/fluid_solver_summation_density.cc). The density then follows the
  /// particles' spacing, so a channel that loses particles through its outlet loses
  /// pressure and draws fluid back, where the continuity density lets it spread thin
  /// unnoticed. A fraction, not the plain sum: a starting lattice beside a curved wall
  /// sums a few per cent off rho0, and the plain sum turns that into a pressure kick at
  /// the first step. Internal flows only: a free surface's truncated support reads as
  /// sparse. Wall and buffer particles keep their own densities.
  double summation_blend = 0;
  /// Dummy wall particles take 2 v_wall - v_fluid(mirror point) instead of the wall's
  /// velocity (the no-slip velocity of English et al.'s modified DBC, 2022): the
  /// no-slip surface is the wall face, not the first dummy layer half a spacing behind
  /// it (sph/fluid_solver_no_slip.cc). Off by default (DualSPHysics' plain DBC).
  bool no_slip_walls = false;
  /// Particle shifting after each step (sph/particle_shifting.h): the coefficient A of
  /// D = A h |v| dt; 0 switches it off. It keeps the particles near a lattice, so voids do
  /// not open behind bodies in an internal flow and pairs do not clump; particles at a
  /// free surface are not shifted.
  double shifting_coefficient = 0;
  TimeScheme scheme = TimeScheme::verlet;
  int verlet_euler_every = 40;
  double cfl = 0.2;
  /// A time step below this stops the run (a collapsing step means a blow-up), s.
  double minimum_time_step = 1e-9;
  /// Fluid particles that leave this box (m), or whose state turns non-finite, are
  /// removed from the run and counted (as DualSPHysics excludes them); a boundary
  /// particle leaving it stops the run.
  Vector domain_min = Vector::Constant(-1), domain_max = Vector::Constant(1);
  /// The run stops once more than this fraction of the fluid particles has been removed.
  double maximum_lost_fraction = 0.01;
  /// A fluid particle whose density leaves [minimum, maximum] * rho0 is removed too:
  /// weakly-compressible water stays within a few per cent of rho0, so such a particle
  /// has passed into a wall or been torn out of the flow, and its pressure (Tait, c0 = 88
  /// m/s: 6 MPa at 1.3 rho0) would catapult it and its neighbours. DualSPHysics' RhopOut
  /// (700 and 1300 kg/m^3 for water).
  double minimum_density_ratio = 0.7, maximum_density_ratio = 1.3;

  double smoothing_length() const
  {
    return smoothing_coefficient * std::sqrt(double(dim)) * particle_spacing;
  }
  double particle_mass() const
  {
    double m = reference_density;
    for (int d = 0; d < dim; ++d)
      m *= particle_spacing;
    return m;
  }
};
} // namespace chipflex::sph
