// `subsection fluid`, `time` and `output` of a case file (apps/case_file.h): the SPH
// fluid's physics and numerics, the time stepping and the output intervals. Every default
// is the initialiser of the struct member the key fills (sph::FluidParameters,
// sph::CaseDescription, CaseFile), so it is defined once.

#include "apps/fluid_case_keys.h"

#include "apps/case_file.h"
#include "apps/case_values.h"
#include "common/input_error.h"

#include <deal.II/base/parameter_handler.h>

namespace chipflex::apps
{
using dealii::ParameterHandler;
using dealii::Patterns::Anything;
using dealii::Patterns::Bool;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;

void declare_fluid_keys(ParameterHandler& prm)
{
  const sph::FluidParameters<2> fluid;
  const sph::CaseDescription<2> description;
  prm.enter_subsection("fluid");
  prm.declare_entry("particle spacing", default_text(fluid.particle_spacing), Double(0),
                    "Initial particle spacing dp, m.");
  prm.declare_entry("smoothing coefficient", default_text(fluid.smoothing_coefficient), Double(0),
                    "h = coefficient * sqrt(dim) * dp (DualSPHysics coefh), -. Kernel support 2h.");
  prm.declare_entry("reference density", default_text(fluid.reference_density), Double(0),
                    "rho0, kg/m^3.");
  prm.declare_entry("speed of sound", default_text(fluid.speed_of_sound), Double(0),
                    "c0, m/s. 0: sound coefficient * sqrt(|g| H), H the highest fluid block.");
  prm.declare_entry("sound coefficient", default_text(description.sound_coefficient), Double(0),
                    "Factor on sqrt(|g| H) when speed of sound = 0 (DualSPHysics coefsound), -.");
  prm.declare_entry("gamma", default_text(fluid.gamma), Double(1), "Tait exponent, -.");
  prm.declare_entry("gravity", "", Anything(),
                    "Gravity vector, m/s^2 (dim components); empty: -9.81 along the last axis.");
  prm.declare_entry("viscosity", "artificial", Selection("artificial|laminar"),
                    "artificial (Monaghan 1992) or laminar (Lo & Shao 2002).");
  prm.declare_entry("artificial viscosity", default_text(fluid.artificial_viscosity), Double(0),
                    "Monaghan's alpha, -.");
  prm.declare_entry("kinematic viscosity", default_text(fluid.kinematic_viscosity), Double(0),
                    "nu for the laminar model, m^2/s.");
  prm.declare_entry("density diffusion", "fourtakas",
                    Selection("none|molteni colagrossi|fourtakas"),
                    "Delta-SPH term: none, molteni colagrossi (2009), fourtakas (2019).");
  prm.declare_entry("density diffusion delta", default_text(fluid.density_diffusion_delta),
                    Double(0), "delta, -.");
  prm.declare_entry("density limits", "", Anything(),
                    "A fluid particle whose density leaves [min, max] is removed and counted "
                    "(it has passed into a wall or been torn out of the flow; DualSPHysics' "
                    "RhopOut), kg/m^3. Empty: 0.7 and 1.3 rho0 (700, 1300 for water).");
  prm.declare_entry("spray tension", "keep", Selection("cut|keep"),
                    "cut: spray (a fluid particle whose kernel support is less than half "
                    "filled) holds no tension, p = max(p, 0), so detached particle pairs do "
                    "not bind and fly apart (experimental: fluid in a corner of Lennard-Jones "
                    "walls counts as spray, docs/sph.md); keep: the plain Tait law everywhere (as "
                    "DualSPHysics).");
  prm.declare_entry("minimum pressure", "", Anything(),
                    "Pressure floor p_min <= 0, Pa: p = max(p_Tait, p_min) for every particle, "
                    "so a stretched particle pair cannot gain more than sqrt(2 |p_min| / rho0) "
                    "when it snaps (-rho0 g H bounds that by the flow's own sqrt(2 g H); "
                    "docs/sph.md). Empty: none (the plain Tait law, as DualSPHysics).");
  prm.declare_entry("background pressure", default_text(fluid.background_pressure), Double(0),
                    "Background (ambient) pressure, Pa, added to the equation of state's "
                    "pressure in the momentum equation: it holds internal flows whole "
                    "behind obstacles (a wake's suction down to minus this value). The "
                    "fluid starts in equilibrium with it; gauges, outputs and open "
                    "boundaries stay gauge pressures. Internal flows only: at a free surface "
                    "or a Lennard-Jones wall it pushes the fluid outwards or into the wall "
                    "(docs/sph.md, \"Background pressure\").");
  prm.declare_entry("density", "continuity", Selection("continuity|summation"),
                    "How the fluid's density is formed. continuity: integrated from the "
                    "continuity equation (DualSPHysics; any flow, free surfaces included). "
                    "summation: the continuity density moved, in every step, `summation "
                    "blend` of the way to the kernel sum rho0 sum_j W_ij / sum_lattice W, so "
                    "it follows the particles' spacing and a channel that loses particles "
                    "through its outlet draws fluid back. Internal flows only: at a free "
                    "surface the truncated support reads as sparse (docs/sph.md, \"Summation "
                    "density\").");
  prm.declare_entry("summation blend", "0.1", Double(0, 1),
                    "With `density = summation`: the fraction of the way from the continuity "
                    "density to the kernel sum taken in every step (1: the plain sum, which "
                    "turns a starting lattice's misfit beside curved walls into a pressure "
                    "kick).");
  prm.declare_entry("no slip walls", fluid.no_slip_walls ? "true" : "false", Bool(),
                    "Dummy wall particles take 2 v_wall - v_fluid at their mirror point across "
                    "the face (the no-slip velocity of the modified DBC, English et al. 2022), "
                    "so the fluid sticks at the wall face rather than at the first dummy "
                    "layer; false: the wall's velocity (DualSPHysics' DBC).");
  prm.declare_entry("particle shifting", "automatic", Selection("automatic|on|off"),
                    "Particle shifting after each step (Fickian, Lind et al. 2012, with "
                    "Skillen et al.'s D = A h |v| dt and Sun et al.'s tensile term): keeps the "
                    "particles near a lattice, so no voids open behind bodies in an internal "
                    "flow and no pairs clump; particles at a free surface are not shifted. "
                    "automatic: on for a case with an inlet or an outlet (an internal flow), "
                    "off otherwise (docs/sph.md, \"Particle shifting\").");
  prm.declare_entry("shifting coefficient", default_text(sph::default_shifting_coefficient),
                    Double(0),
                    "A in the shift's diffusion coefficient D = A h |v| dt (2, as DualSPHysics).");
  prm.declare_entry("hydrostatic start", description.hydrostatic_start ? "true" : "false", Bool(),
                    "Start each fluid block with its hydrostatic density (no initial wave).");
  prm.leave_subsection();

  prm.enter_subsection("rotating frame");
  prm.declare_entry("angular velocity", "0, 0, 0", Anything(),
                    "The case's frame turns at this angular velocity (rad/s, three components, "
                    "world axes; 2D: 0, 0, omega_z), e.g. the drill's frame: its walls stand "
                    "still, and every fluid particle and rigid or flexible body feels the "
                    "centrifugal, Coriolis and Euler accelerations. 0, 0, 0: an inertial frame.");
  prm.declare_entry("axis point", "", Anything(),
                    "A point on the axis of rotation, m (dim components); empty: the origin.");
  prm.declare_entry("spin-up time", "0", Double(0),
                    "The frame's speed rises from 0 to the angular velocity over this time, "
                    "smoothly ((1 - cos(pi t / T)) / 2), s. 0: it turns from the start.");
  prm.leave_subsection();

  prm.enter_subsection("time");
  prm.declare_entry("end time", default_text(description.end_time), Double(0),
                    "Simulated time, s.");
  prm.declare_entry("scheme", "automatic", Selection("automatic|verlet|symplectic|position verlet"),
                    "verlet (Euler every `verlet euler every` steps), symplectic (two force "
                    "passes per step) or position verlet (the same drift-kick-drift step "
                    "with one pass; docs/sph.md). automatic: position verlet for a case with "
                    "bodies (the coupling's momentum exchange is exact only with the "
                    "symplectic schemes), verlet for a fluid alone.");
  prm.declare_entry("cfl", default_text(fluid.cfl), Double(0),
                    "Courant number on the CFL and force limits, -.");
  prm.declare_entry("verlet euler every", std::to_string(fluid.verlet_euler_every), Integer(1),
                    "Verlet: an Euler step every N steps.");
  prm.declare_entry("minimum time step", default_text(fluid.minimum_time_step), Double(0),
                    "A time step below this stops the run (blow-up), s.");
  prm.leave_subsection();

  prm.enter_subsection("output");
  prm.declare_entry("frame interval", default_text(description.output_interval), Double(0),
                    "Simulated time between particle frames (particles.xdmf), s.");
  prm.declare_entry("probe interval", default_text(CaseFile{}.probe_interval), Double(0),
                    "Simulated time between rows of probes.csv, s.");
  prm.leave_subsection();
}

template <int dim>
std::string read_fluid_keys(ParameterHandler& prm, sph::CaseDescription<dim>& c)
{
  auto& f = c.fluid;
  prm.enter_subsection("fluid");
  f.particle_spacing = prm.get_double("particle spacing");
  if (!(f.particle_spacing > 0))
    throw InputError("fluid/particle spacing", "must be positive");
  f.smoothing_coefficient = prm.get_double("smoothing coefficient");
  f.reference_density = prm.get_double("reference density");
  f.speed_of_sound = prm.get_double("speed of sound");
  c.sound_coefficient = prm.get_double("sound coefficient");
  f.gamma = prm.get_double("gamma");
  f.gravity = Eigen::Matrix<double, dim, 1>::Zero();
  f.gravity[dim - 1] = -9.81;
  if (!trim(prm.get("gravity")).empty())
    f.gravity = vector_of<dim>("fluid/gravity", prm.get("gravity"));
  f.viscosity = prm.get("viscosity") == "laminar" ? sph::ViscosityModel::laminar
                                                  : sph::ViscosityModel::artificial;
  f.artificial_viscosity = prm.get_double("artificial viscosity");
  f.kinematic_viscosity = prm.get_double("kinematic viscosity");
  const std::string diffusion = prm.get("density diffusion");
  f.density_diffusion = diffusion == "none"        ? sph::DensityDiffusionModel::none
                        : diffusion == "fourtakas" ? sph::DensityDiffusionModel::fourtakas
                                                   : sph::DensityDiffusionModel::molteni_colagrossi;
  f.density_diffusion_delta = prm.get_double("density diffusion delta");
  f.cut_spray_tension = prm.get("spray tension") == "cut";
  f.background_pressure = prm.get_double("background pressure");
  if (!trim(prm.get("minimum pressure")).empty())
  {
    const auto p_min = numbers("fluid/minimum pressure", prm.get("minimum pressure"));
    if (p_min.size() != 1 || !(p_min[0] <= 0))
      throw InputError("fluid/minimum pressure",
                       "must be one number <= 0 (Pa), got '" + prm.get("minimum pressure") + "'");
    f.minimum_pressure = p_min[0];
  }
  {
    const std::string text = prm.get("density limits");
    const auto limits = trim(text).empty() ? std::vector<double>{0.7 * f.reference_density,
                                                                 1.3 * f.reference_density}
                                           : numbers("fluid/density limits", text);
    if (limits.size() != 2 || !(limits[0] >= 0) || !(limits[1] > limits[0]) ||
        !(limits[0] < f.reference_density && limits[1] > f.reference_density))
      throw InputError("fluid/density limits",
                       "'" + prm.get("density limits") + "': two densities min < rho0 < max");
    f.minimum_density_ratio = limits[0] / f.reference_density;
    f.maximum_density_ratio = limits[1] / f.reference_density;
  }
  f.no_slip_walls = prm.get_bool("no slip walls");
  f.summation_blend = prm.get("density") == "summation" ? prm.get_double("summation blend") : 0;
  const std::string shifting = prm.get("particle shifting");
  f.shifting_coefficient = shifting == "off" ? 0 : prm.get_double("shifting coefficient");
  c.hydrostatic_start = prm.get_bool("hydrostatic start");
  prm.leave_subsection();

  prm.enter_subsection("rotating frame");
  {
    RotatingFrame& frame = f.rotating_frame;
    frame.angular_velocity =
        vector_of<3>("rotating frame/angular velocity", prm.get("angular velocity"));
    if (dim == 2 && frame.angular_velocity.head<2>().norm() > 0)
      throw InputError("rotating frame/angular velocity",
                       "a 2D case turns about z, the out-of-plane axis: give 0, 0, omega_z");
    frame.axis_point.setZero();
    if (!trim(prm.get("axis point")).empty())
      frame.axis_point.head<dim>() =
          vector_of<dim>("rotating frame/axis point", prm.get("axis point"));
    frame.spin_up_time = prm.get_double("spin-up time");
  }
  prm.leave_subsection();

  prm.enter_subsection("time");
  c.end_time = prm.get_double("end time");
  const std::string scheme = prm.get("scheme");
  f.scheme = scheme == "symplectic"        ? sph::TimeScheme::symplectic
             : scheme == "position verlet" ? sph::TimeScheme::position_verlet
                                           : sph::TimeScheme::verlet;
  f.cfl = prm.get_double("cfl");
  f.verlet_euler_every = prm.get_integer("verlet euler every");
  f.minimum_time_step = prm.get_double("minimum time step");
  prm.leave_subsection();

  prm.enter_subsection("output");
  c.output_interval = prm.get_double("frame interval");
  prm.leave_subsection();
  return shifting;
}

template std::string read_fluid_keys(ParameterHandler&, sph::CaseDescription<2>&);
template std::string read_fluid_keys(ParameterHandler&, sph::CaseDescription<3>&);
} // namespace chipflex::apps
