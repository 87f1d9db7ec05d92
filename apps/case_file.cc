#include "apps/case_file.h"

#include "apps/body_case_keys.h"
#include "apps/contact_case_keys.h"
#include "common/input_error.h"
#include "coupling/fluid_overlap.h"
#include "meshes/surface_mesh.h"

#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace chipflex::apps
{
using dealii::ParameterHandler;
using dealii::Patterns::Anything;
using dealii::Patterns::Bool;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;

namespace
{
sph::WallModel wall_model_of(const std::string& key)
{
  return key == "lennard jones" ? sph::WallModel::lennard_jones
         : key == "thin skin"   ? sph::WallModel::thin_skin
                                : sph::WallModel::dummy_particles;
}

void declare_keys(ParameterHandler& prm, int n_bodies)
{
  prm.declare_entry("dimension", "2", Integer(2, 3), "Space dimension: 2 (per metre depth) or 3.");
  prm.enter_subsection("fluid");
  prm.declare_entry("particle spacing", "0.01", Double(0), "Initial particle spacing dp, m.");
  prm.declare_entry("smoothing coefficient", "1", Double(0),
                    "h = coefficient * sqrt(dim) * dp (DualSPHysics coefh), -. Kernel support 2h.");
  prm.declare_entry("reference density", "1000", Double(0), "rho0, kg/m^3.");
  prm.declare_entry("speed of sound", "0", Double(0),
                    "c0, m/s. 0: sound coefficient * sqrt(|g| H), H the highest fluid block.");
  prm.declare_entry("sound coefficient", "20", Double(0),
                    "Factor on sqrt(|g| H) when speed of sound = 0 (DualSPHysics coefsound), -.");
  prm.declare_entry("gamma", "7", Double(1), "Tait exponent, -.");
  prm.declare_entry("gravity", "", Anything(),
                    "Gravity vector, m/s^2 (dim components); empty: -9.81 along the last axis.");
  prm.declare_entry("viscosity", "artificial", Selection("artificial|laminar"),
                    "artificial (Monaghan 1992) or laminar (Lo & Shao 2002).");
  prm.declare_entry("artificial viscosity", "0.02", Double(0), "Monaghan's alpha, -.");
  prm.declare_entry("kinematic viscosity", "1e-6", Double(0), "nu for the laminar model, m^2/s.");
  prm.declare_entry("density diffusion", "fourtakas",
                    Selection("none|molteni colagrossi|fourtakas"),
                    "Delta-SPH term: none, molteni colagrossi (2009), fourtakas (2019).");
  prm.declare_entry("density diffusion delta", "0.1", Double(0), "delta, -.");
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
  prm.declare_entry("background pressure", "0", Double(0),
                    "Background (ambient) pressure, Pa, added to the equation of state's "
                    "pressure in the momentum equation: it holds internal flows whole "
                    "behind obstacles (a wake's suction down to minus this value). The "
                    "fluid starts in equilibrium with it; gauges, outputs and open "
                    "boundaries stay gauge pressures. Internal flows only: at a free surface "
                    "or a Lennard-Jones wall it pushes the fluid outwards or into the wall "
                    "(docs/sph.md, \"Background pressure\").");
  prm.declare_entry("no slip walls", "false", Bool(),
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
  prm.declare_entry("shifting coefficient", "2", Double(0),
                    "A in the shift's diffusion coefficient D = A h |v| dt (2, as DualSPHysics).");
  prm.declare_entry("hydrostatic start", "true", Bool(),
                    "Start each fluid block with its hydrostatic density (no initial wave).");
  prm.leave_subsection();

  prm.enter_subsection("time");
  prm.declare_entry("end time", "1", Double(0), "Simulated time, s.");
  prm.declare_entry("scheme", "automatic", Selection("automatic|verlet|symplectic|position verlet"),
                    "verlet (Euler every `verlet euler every` steps), symplectic (two force "
                    "passes per step) or position verlet (the same drift-kick-drift step "
                    "with one pass; docs/sph.md). automatic: position verlet for a case with "
                    "bodies (the coupling's momentum exchange is exact only with the "
                    "symplectic schemes), verlet for a fluid alone.");
  prm.declare_entry("cfl", "0.2", Double(0), "Courant number on the CFL and force limits, -.");
  prm.declare_entry("verlet euler every", "40", Integer(1), "Verlet: an Euler step every N steps.");
  prm.declare_entry("minimum time step", "1e-9", Double(0),
                    "A time step below this stops the run (blow-up), s.");
  prm.leave_subsection();

  prm.enter_subsection("output");
  prm.declare_entry("frame interval", "0.01", Double(0),
                    "Simulated time between particle frames (particles.xdmf), s.");
  prm.declare_entry("probe interval", "0.001", Double(0),
                    "Simulated time between rows of probes.csv, s.");
  prm.leave_subsection();

  prm.enter_subsection("geometry");
  prm.declare_entry("fluid blocks", "0, 0, 1, 2", Anything(),
                    "Fluid boxes 'min corner, max corner' (2*dim numbers, m), separated by ';'.");
  prm.declare_entry("domain min", "", Anything(),
                    "The domain box, m: a fluid particle that leaves it is removed from the "
                    "run and counted (lost_particles in the log, probes and summary). Empty: "
                    "automatic (everything plus a quarter of its size on every side).");
  prm.declare_entry("domain max", "", Anything(), "See domain min, m.");
  prm.declare_entry("initial velocity", "", Anything(),
                    "Velocity of the fluid blocks at t = 0 (dim components), m/s; empty: at rest.");
  prm.declare_entry("fluid region", "", Anything(),
                    "'FILE [group NAME] [flip]': a closed surface (gmsh .msh or STL, m; normals "
                    "outwards, `flip` reverses them); fluid-block and buffer particles start "
                    "only inside it, at least dp/2 from its faces (a duct whose section is not "
                    "a box). Empty: the blocks as they are.");
  prm.declare_entry("lost fraction limit", "0.01", Double(0, 1),
                    "The run stops (its last checkpoint kept) once more than this fraction of "
                    "the fluid particles has left the domain box or turned non-finite, -.");
  prm.enter_subsection("tank");
  prm.declare_entry("enabled", "true", Bool(), "A box tank around the fluid.");
  prm.declare_entry("min corner", "0, 0", Anything(), "Inner faces of the tank walls, m.");
  prm.declare_entry("max corner", "4, 3", Anything(), "Inner faces of the tank walls, m.");
  prm.declare_entry("open top", "true", Bool(), "No lid.");
  prm.declare_entry("open ends", "none", Selection("none|x|y|z"),
                    "Leave out the two walls normal to this axis: a channel (2D) or duct (3D, "
                    "with open top = false) whose fluid enters and leaves through open "
                    "boundaries. The walls must span the buffers.");
  prm.declare_entry("wall model", "dummy particles", Selection("dummy particles|lennard jones"),
                    "dummy particles (dynamic boundary condition) or lennard jones.");
  prm.declare_entry("dummy layers", "0", Integer(0),
                    "Dummy particle layers; 0: enough to cover the kernel support (2h).");
  prm.declare_entry("lennard jones k", "0", Double(0),
                    "Wall force scale F(0) per unit mass, m/s^2; 0: 10 p_e / (rho0 dp), "
                    "p_e = rho0 (c0/10)^2.");
  prm.declare_entry("lennard jones R", "0", Double(0), "Cut-off distance, m; 0: dp.");
  prm.declare_entry("lennard jones r0", "0", Double(0), "Equilibrium distance, m; 0: dp/2.");
  prm.leave_subsection();
  prm.enter_subsection("walls");
  prm.declare_entry("polylines", "", Anything(),
                    "2D only: extra walls 'x1, y1, x2, y2, ...' (m), separated by ';'; the "
                    "fluid side is on the right of the direction of travel.");
  prm.declare_entry(
      "surfaces", "", Anything(),
      "Walls from surface meshes, separated by ';', each 'FILE [group NAME] "
      "[flip] [barrier]': a gmsh .msh (2D: its lines; 3D: its triangles and quads, or the "
      "boundary of its elements) or an STL file (3D), m. The fluid lies on the "
      "side of the face normals (`flip` reverses them); relative names are looked "
      "up beside the case file. `barrier`: a permeable barrier (bodies feel it, "
      "the fluid does not; subsection contact).");
  prm.declare_entry("wall model", "lennard jones",
                    Selection("dummy particles|lennard jones|thin skin"),
                    "Model of the extra walls. thin skin: a wall with fluid on both sides "
                    "(sided dummy particles; docs/sph.md, \"Thin skins\").");
  prm.declare_entry("fluid passes", "", Anything(),
                    "Numbers (1-based, comma-separated) of the polylines that are permeable "
                    "barriers: bodies feel them (subsection contact), the fluid does not.");
  prm.leave_subsection();
  prm.leave_subsection();

  // Open boundaries (sph/open_boundary.h, docs/sph.md "Open boundaries").
  prm.enter_subsection("open boundaries");
  prm.declare_entry("tear warning fraction", "0.05", Double(0),
                    "An internal flow holds its volume: when the fluid particles in the domain "
                    "fall more than this fraction below their number at the start (the "
                    "outlets taking out more than the inlets bring, a void opening), the run "
                    "says so in the log and in summary.txt (`continuity:` line, torn=yes). "
                    ">= 1: off (a tank that drains on purpose).");
  prm.declare_entry("watched frequencies", "", Anything(),
                    "Frequencies the case is meant to resolve (a forcing, a vortex shedding, an "
                    "expected body response), Hz, comma-separated. `chipflex run` warns when "
                    "the channel's acoustic frequency c0 / (4 L) lies within a factor of 3 of "
                    "one of them or of a flexible body's first natural frequency (docs/sph.md, "
                    "\"Choosing c0 for channels\").");
  for (const char* zone : {"inlet", "outlet"})
  {
    const bool inlet = std::string(zone) == "inlet";
    prm.enter_subsection(zone);
    prm.declare_entry("enabled", "false", Bool(),
                      inlet ? "A velocity inlet: buffer particles at a prescribed velocity, "
                              "density extrapolated from the fluid; new particles enter the "
                              "fluid as buffer particles cross the plane."
                            : "A pressure outlet: buffer particles at a prescribed pressure, "
                              "velocity extrapolated from the fluid; particles leaving the "
                              "buffer's far face are removed (outflow_particles).");
    prm.declare_entry("box min", "", Anything(),
                      "The buffer box's min corner, m (dim components). Its face on the fluid "
                      "side is the boundary plane; across the flow it spans the section.");
    prm.declare_entry("box max", "", Anything(), "The buffer box's max corner, m.");
    prm.declare_entry("direction", "+x", Selection("+x|-x|+y|-y|+z|-z"),
                      "The flow direction through the boundary (an inlet's points into the "
                      "fluid, an outlet's out of it).");
    prm.declare_entry("layers", "4", Integer(1),
                      "Buffer layers: the box's depth along the flow is layers * dp (at least "
                      "the kernel support 2h; DualSPHysics' default is 4), -.");
    if (inlet)
    {
      prm.declare_entry("velocity", "0", Double(0),
                        "Mean normal speed over the section, m/s (give this or flow rate).");
      prm.declare_entry("flow rate", "0", Double(0),
                        "Volume flow rate, m^3/s (2D: m^2/s per metre depth); the mean speed "
                        "is flow rate / section area.");
      prm.declare_entry("profile", "uniform", Selection("uniform|parabolic"),
                        "uniform, or parabolic across the section: 2D 1.5 U (1 - eta^2) (plane "
                        "Poiseuille), 3D 2.25 U (1 - eta1^2)(1 - eta2^2), eta in [-1, 1].");
      prm.declare_entry("ramp time", "0", Double(0),
                        "The speed rises as (1 - cos(pi t/T))/2 over [0, T], s; 0: at once.");
    }
    else
      prm.declare_entry("pressure", "0", Double(),
                        "Pressure at the centre of the section, Pa (gauge; hydrostatic "
                        "across the section with gravity).");
    prm.leave_subsection();
  }
  prm.leave_subsection();

  prm.enter_subsection("probes");
  prm.declare_entry("pressure", "", Anything(),
                    "Pressure gauges 'name: x, y[, z]' (m), separated by ';' -> p_<name>_Pa.");
  prm.declare_entry("water height", "", Anything(),
                    "Water-height gauges 'name: x, y[, z]' (m; the vertical coordinate is "
                    "ignored), separated by ';' -> h_<name>_m (surface elevation).");
  prm.declare_entry("flow rate", "", Anything(),
                    "Flow-rate gauges, separated by ';'. 2D: 'name: x0, y0, x1, y1' (m, the "
                    "section from (x0, y0) to (x1, y1)) -> q_<name>_m2_s (volume flow, m^2/s "
                    "per metre of depth, positive to the right of the section's direction). "
                    "3D: 'name: x, y, z, nx, ny, nz' (the whole plane through the point, "
                    "normal n) -> q_<name>_m3_s (m^3/s, positive along n).");
  prm.leave_subsection();
  declare_body_keys(prm, n_bodies);
  declare_contact_keys(prm);
}

std::string trim(const std::string& s)
{
  const auto a = s.find_first_not_of(" \t\n");
  if (a == std::string::npos)
    return "";
  return s.substr(a, s.find_last_not_of(" \t\n") - a + 1);
}

std::vector<std::string> split(const std::string& s, char separator)
{
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, separator))
    if (!trim(item).empty())
      out.push_back(trim(item));
  return out;
}

std::vector<double> numbers(const std::string& key, const std::string& text)
{
  std::vector<double> out;
  for (const auto& item : split(text, ','))
  {
    std::size_t used = 0;
    double v = 0;
    try
    {
      v = std::stod(item, &used);
    }
    catch (const std::exception&)
    {
      used = 0;
    }
    if (used != item.size())
      throw InputError(key, "'" + text + "' is not a list of numbers");
    out.push_back(v);
  }
  return out;
}

template <int dim>
Eigen::Matrix<double, dim, 1> vector_of(const std::string& key, const std::string& text)
{
  const auto v = numbers(key, text);
  if (v.size() != dim)
    throw InputError(key, "'" + text + "' needs " + std::to_string(dim) + " components");
  return Eigen::Map<const Eigen::Matrix<double, dim, 1>>(v.data());
}

template <int dim>
std::vector<sph::Probe<dim>> probes_of(const std::string& key, const std::string& text)
{
  std::vector<sph::Probe<dim>> out;
  for (const auto& item : split(text, ';'))
  {
    const auto colon = item.find(':');
    if (colon == std::string::npos || trim(item.substr(0, colon)).empty())
      throw InputError(key, "'" + item + "' is not 'name: x, y" + (dim == 3 ? ", z'" : "'"));
    const std::string name = trim(item.substr(0, colon));
    if (name.find_first_of(" ,\"") != std::string::npos)
      throw InputError(key, "probe name '" + name + "' must not contain spaces, commas or quotes");
    out.push_back({name, vector_of<dim>(key, item.substr(colon + 1))});
  }
  return out;
}

/// A surface given as 'FILE [group NAME] [flip]' (with `barrier` when `barrier` is not
/// null); relative names are looked up beside the case file.
template <int dim>
meshes::SurfaceMesh<dim> read_surface_spec(const std::string& key, const std::string& spec,
                                           const std::string& case_path, bool* barrier)
{
  std::istringstream words(spec);
  std::string file, word, group;
  bool flip = false;
  words >> file;
  while (words >> word)
    if (word == "flip")
      flip = true;
    else if (word == "barrier" && barrier)
      *barrier = true;
    else if (word == "group" && (words >> group))
      continue;
    else
      throw InputError(key, "'" + spec + "': expected 'FILE [group NAME] [flip]" +
                                (barrier ? std::string(" [barrier]'") : std::string("'")));
  namespace fs = std::filesystem;
  const fs::path beside = fs::path(case_path).parent_path() / file;
  if (!fs::path(file).is_absolute() && fs::exists(beside))
    file = beside.string();
  return meshes::read_surface_mesh<dim>(file, group, flip);
}

template <int dim>
std::vector<sph::FlowSection> sections_of(const std::string& key, const std::string& text)
{
  std::vector<sph::FlowSection> out;
  const std::string numbers_form = dim == 2 ? "x0, y0, x1, y1" : "x, y, z, nx, ny, nz";
  const std::string form = "'name: " + numbers_form + "'";
  for (const auto& item : split(text, ';'))
  {
    const auto colon = item.find(':');
    if (colon == std::string::npos || trim(item.substr(0, colon)).empty())
      throw InputError(key, "'" + item + "' is not " + form);
    const std::string name = trim(item.substr(0, colon));
    if (name.find_first_of(" ,\"") != std::string::npos)
      throw InputError(key, "gauge name '" + name + "' must not contain spaces, commas or quotes");
    const auto v = numbers(key, item.substr(colon + 1));
    if (v.size() != 2 * std::size_t(dim))
      throw InputError(key, "'" + item + "' needs " + std::to_string(2 * dim) +
                                " numbers: " + numbers_form);
    sph::FlowSection section;
    section.name = name;
    if constexpr (dim == 2)
    {
      section.a = Eigen::Vector2d(v[0], v[1]);
      section.b = Eigen::Vector2d(v[2], v[3]);
      if (!((section.b - section.a).norm() > 0))
        throw InputError(key, "'" + item + "': the section has zero length");
    }
    else
    {
      section.point = Eigen::Vector3d(v[0], v[1], v[2]);
      section.normal = Eigen::Vector3d(v[3], v[4], v[5]);
      if (!(section.normal.norm() > 0))
        throw InputError(key, "'" + item + "': the normal is zero");
      section.normal.normalize();
    }
    out.push_back(section);
  }
  return out;
}

template <int dim>
void fill(ParameterHandler& prm, sph::CaseDescription<dim>& c, const std::string& case_path)
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
  const std::string shifting = prm.get("particle shifting");
  const double shifting_coefficient = prm.get_double("shifting coefficient");
  c.hydrostatic_start = prm.get_bool("hydrostatic start");
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

  prm.enter_subsection("geometry");
  for (const auto& block : split(prm.get("fluid blocks"), ';'))
  {
    const auto v = numbers("geometry/fluid blocks", block);
    if (v.size() != 2 * dim)
      throw InputError("geometry/fluid blocks",
                       "'" + block + "' needs " + std::to_string(2 * dim) + " numbers");
    sph::FluidBlock<dim> b;
    for (int d = 0; d < dim; ++d)
      b.min[d] = v[d], b.max[d] = v[dim + d];
    if (!((b.max - b.min).minCoeff() > 0))
      throw InputError("geometry/fluid blocks", "'" + block + "': max corner must exceed min");
    c.fluid_blocks.push_back(b);
  }
  const std::string dmin = prm.get("domain min"), dmax = prm.get("domain max");
  c.automatic_domain = trim(dmin).empty() && trim(dmax).empty();
  if (!c.automatic_domain)
  {
    f.domain_min = vector_of<dim>("geometry/domain min", dmin);
    f.domain_max = vector_of<dim>("geometry/domain max", dmax);
  }
  f.maximum_lost_fraction = prm.get_double("lost fraction limit");
  if (!trim(prm.get("initial velocity")).empty())
    c.initial_velocity = vector_of<dim>("geometry/initial velocity", prm.get("initial velocity"));
  if (!trim(prm.get("fluid region")).empty())
  {
    const auto mesh = read_surface_spec<dim>("geometry/fluid region", prm.get("fluid region"),
                                             case_path, nullptr);
    auto region = std::make_shared<coupling::SkinOverlap<dim>>(mesh.vertices, mesh.faces,
                                                               0.5 * c.fluid.particle_spacing);
    if (!region->closed())
      throw InputError("geometry/fluid region", "the surface is not closed");
    c.fluid_region = [region](const Eigen::Matrix<double, dim, 1>& x)
    { return region->encloses(x) && !region->near_face(x); };
  }
  prm.enter_subsection("tank");
  c.tank.enabled = prm.get_bool("enabled");
  c.tank.min = vector_of<dim>("geometry/tank/min corner", prm.get("min corner"));
  c.tank.max = vector_of<dim>("geometry/tank/max corner", prm.get("max corner"));
  if (c.tank.enabled && !((c.tank.max - c.tank.min).minCoeff() > 0))
    throw InputError("geometry/tank/max corner", "must lie above the min corner");
  c.tank.open_top = prm.get_bool("open top");
  {
    const std::string ends = prm.get("open ends");
    c.tank.open_axis = ends == "none" ? -1 : ends[0] - 'x';
    if (c.tank.open_axis >= dim)
      throw InputError("geometry/tank/open ends", "'" + ends + "' in a 2D case");
  }
  c.tank.model = wall_model_of(prm.get("wall model"));
  c.tank.layers = prm.get_integer("dummy layers");
  c.tank.lennard_jones = {prm.get_double("lennard jones k"), prm.get_double("lennard jones R"),
                          prm.get_double("lennard jones r0")};
  prm.leave_subsection();
  prm.enter_subsection("walls");
  const auto lines = split(prm.get("polylines"), ';');
  if (!lines.empty() && dim != 2)
    throw InputError("geometry/walls/polylines", "extra polyline walls are 2D only");
  for (std::size_t k = 0; k < lines.size(); ++k)
  {
    const auto v = numbers("geometry/walls/polylines", lines[k]);
    if (v.size() < 4 || v.size() % 2)
      throw InputError("geometry/walls/polylines", "'" + lines[k] + "' needs x, y pairs (>= 2)");
    sph::WallSurface<dim> w;
    w.name = "wall " + std::to_string(k + 1);
    w.model = wall_model_of(prm.get("wall model"));
    for (std::size_t i = 0; i + 1 < v.size(); i += 2)
    {
      Eigen::Matrix<double, dim, 1> x = Eigen::Matrix<double, dim, 1>::Zero();
      x[0] = v[i], x[1] = v[i + 1];
      w.vertices.push_back(x);
    }
    for (int i = 0; i + 1 < int(w.vertices.size()); ++i)
    {
      std::array<int, dim> face{};
      face[0] = i, face[1] = i + 1;
      w.faces.push_back(face);
    }
    c.walls.push_back(w);
  }
  for (double k : numbers("geometry/walls/fluid passes", prm.get("fluid passes")))
  {
    if (k != std::floor(k) || k < 1 || k > double(c.walls.size()))
    {
      std::ostringstream what;
      what << "no polyline " << k << " (there are " << c.walls.size() << ")";
      throw InputError("geometry/walls/fluid passes", what.str());
    }
    c.walls[std::size_t(k) - 1].fluid_passes = true;
  }
  const auto surfaces = split(prm.get("surfaces"), ';');
  for (std::size_t k = 0; k < surfaces.size(); ++k)
  {
    bool barrier = false;
    const auto mesh =
        read_surface_spec<dim>("geometry/walls/surfaces", surfaces[k], case_path, &barrier);
    sph::WallSurface<dim> w;
    w.name = "surface " + std::to_string(k + 1);
    w.model = wall_model_of(prm.get("wall model"));
    w.vertices = mesh.vertices;
    w.faces = mesh.faces;
    w.fluid_passes = barrier;
    c.walls.push_back(w);
  }
  prm.leave_subsection();
  prm.leave_subsection();

  prm.enter_subsection("open boundaries");
  for (const char* name : {"inlet", "outlet"})
  {
    prm.enter_subsection(name);
    const std::string where = std::string("open boundaries/") + name;
    if (prm.get_bool("enabled"))
    {
      sph::OpenBoundary<dim> z;
      z.name = name;
      z.kind = z.name == "inlet" ? sph::OpenBoundaryKind::inlet : sph::OpenBoundaryKind::outlet;
      const std::string direction = prm.get("direction");
      z.sign = direction[0] == '+' ? 1 : -1;
      z.axis = direction[1] - 'x';
      if (z.axis >= dim)
        throw InputError(where + "/direction", "'" + direction + "' in a 2D case");
      z.box_min = vector_of<dim>(where + "/box min", prm.get("box min"));
      z.box_max = vector_of<dim>(where + "/box max", prm.get("box max"));
      if (!((z.box_max - z.box_min).minCoeff() > 0))
        throw InputError(where + "/box max", "must exceed the box min corner in every component");
      // The box's extent along the flow is its plane face and `layers` spacings behind it.
      const double depth = prm.get_integer("layers") * f.particle_spacing;
      const double plane = z.plane();
      const bool upper = (z.kind == sph::OpenBoundaryKind::inlet) == (z.sign > 0);
      if (std::abs(z.thickness() - depth) > 1e-6 * depth)
      {
        std::ostringstream s;
        s << "the box is " << z.thickness() << " m deep along " << direction
          << ", layers * dp = " << depth << " m: make them agree";
        throw InputError(where + "/layers", s.str());
      }
      if (upper)
        z.box_min[z.axis] = plane - depth;
      else
        z.box_max[z.axis] = plane + depth;
      if (z.kind == sph::OpenBoundaryKind::inlet)
      {
        const double u = prm.get_double("velocity"), q = prm.get_double("flow rate");
        if ((u > 0) == (q > 0))
          throw InputError(where, "give exactly one of velocity and flow rate (positive)");
        z.velocity = u > 0 ? u : q / z.section_area();
        z.profile = prm.get("profile") == "parabolic" ? sph::InletProfile::parabolic
                                                      : sph::InletProfile::uniform;
        z.ramp_time = prm.get_double("ramp time");
      }
      else
        z.pressure = prm.get_double("pressure");
      c.open_boundaries.push_back(z);
    }
    prm.leave_subsection();
  }
  prm.leave_subsection();

  // An internal flow (an inlet or an outlet) is shifted unless the case says otherwise.
  const bool shift = shifting == "on" || (shifting == "automatic" && !c.open_boundaries.empty());
  f.shifting_coefficient = shift ? shifting_coefficient : 0;

  prm.enter_subsection("probes");
  c.pressure_probes = probes_of<dim>("probes/pressure", prm.get("pressure"));
  c.height_probes = probes_of<dim>("probes/water height", prm.get("water height"));
  c.flow_sections = sections_of<dim>("probes/flow rate", prm.get("flow rate"));
  prm.leave_subsection();
}

/// deal.II's exception text is a multi-line block; keep its "additional information"
/// as one line.
std::string one_line(const std::string& what)
{
  std::string s = what;
  const auto info = s.find("Additional information:");
  if (info != std::string::npos)
    s = s.substr(info + 23);
  const auto stack = s.find("Stacktrace:");
  if (stack != std::string::npos)
    s = s.substr(0, stack);
  std::string out;
  bool space = false;
  for (char ch : s)
  {
    if (ch == '\n' || ch == '\t' || ch == ' ')
      space = !out.empty();
    else
    {
      if (space)
        out += ' ';
      out += ch;
      space = false;
    }
  }
  while (!out.empty() && (out.back() == '-' || out.back() == ' '))
    out.pop_back();
  return out;
}
} // namespace

// declare_body_keys(): apps/body_case_keys.cc (the coupled bodies' keys).

std::string documented_case_keys()
{
  ParameterHandler prm;
  declare_keys(prm, 1);
  std::ostringstream out;
  prm.print_parameters(out, ParameterHandler::OutputStyle::PRM);
  return out.str();
}

namespace
{
/// The case file's text with every `include FILE` line (FILE relative to the case file's
/// folder) given as an absolute path, for ParameterHandler, which reads the included file
/// in its place (so its errors name that file and its line); and, in `expanded`, the text
/// with each included file written out, for what must see the whole case before it is
/// parsed (the body subsections). One level: an included file includes nothing.
/// Where an `include ` statement starts in `line`, or npos.
std::size_t include_at(const std::string& line)
{
  const std::size_t first = line.find_first_not_of(" \t");
  return first != std::string::npos && line.compare(first, 8, "include ") == 0 ? first
                                                                               : std::string::npos;
}

std::string resolve_includes(const std::string& path, std::string& expanded)
{
  std::ifstream in(path);
  if (!in)
    throw InputError(path, "cannot open the case file");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::string resolved, line;
  expanded.clear();
  for (int line_number = 1; std::getline(in, line); ++line_number)
  {
    const std::size_t first = include_at(line);
    if (first == std::string::npos)
    {
      resolved += line + "\n";
      expanded += line + "\n";
      continue;
    }
    const std::string where = path + ": line " + std::to_string(line_number);
    std::string name = line.substr(first + 8);
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t\r") + 1);
    if (name.empty())
      throw InputError(where, "include: no file name");
    const std::filesystem::path file = std::filesystem::absolute(folder / name);
    std::ifstream included(file);
    if (!included)
      throw InputError(where, "include " + name + ": cannot open " + file.string());
    std::stringstream text;
    text << included.rdbuf();
    std::istringstream lines(text.str());
    for (std::string l; std::getline(lines, l);)
      if (include_at(l) != std::string::npos)
        throw InputError(file.string(), "include inside an included file (one level only)");
    resolved += "include " + file.string() + "\n";
    expanded += text.str() + "\n";
  }
  return resolved;
}
} // namespace

CaseFile read_case_file(const std::string& path)
{
  std::string expanded;
  std::stringstream text(resolve_includes(path, expanded));
  CaseFile c;
  c.path = path;
  c.parameters = std::make_shared<ParameterHandler>();
  auto& prm = *c.parameters;
  c.body_subsections = count_body_subsections(expanded);
  declare_keys(prm, c.body_subsections);
  try
  {
    prm.parse_input(text, path, "", false);
  }
  catch (const dealii::ExceptionBase& e)
  {
    throw InputError(path, one_line(e.what()));
  }
  try
  {
    c.dimension = int(prm.get_integer("dimension"));
    if (c.dimension == 2)
      fill(prm, c.case_2d, path);
    else
      fill(prm, c.case_3d, path);
    prm.enter_subsection("time");
    const bool automatic_scheme = prm.get("scheme") == "automatic";
    prm.leave_subsection();
    if (n_case_bodies(prm, c.body_subsections) > 0)
    {
      if (automatic_scheme)
        c.case_2d.fluid.scheme = c.case_3d.fluid.scheme = sph::TimeScheme::position_verlet;
      // The Verlet step's velocity update spans two steps, so the coupling's momentum
      // exchange would not be exact (docs/coupling.md).
      if (!sph::is_symplectic(c.dimension == 2 ? c.case_2d.fluid.scheme : c.case_3d.fluid.scheme))
        throw InputError("time/scheme", "'verlet': a case with bodies needs symplectic or "
                                        "position verlet (or automatic, the default)");
    }
    c.end_time = c.dimension == 2 ? c.case_2d.end_time : c.case_3d.end_time;
    c.frame_interval = c.dimension == 2 ? c.case_2d.output_interval : c.case_3d.output_interval;
    prm.enter_subsection("output");
    c.probe_interval = prm.get_double("probe interval");
    prm.leave_subsection();
    const bool open =
        c.dimension == 2 ? !c.case_2d.open_boundaries.empty() : !c.case_3d.open_boundaries.empty();
    prm.enter_subsection("open boundaries");
    if (open)
      c.tear_warning_fraction = prm.get_double("tear warning fraction");
    for (double f : numbers("open boundaries/watched frequencies", prm.get("watched frequencies")))
    {
      if (!(f > 0))
        throw InputError("open boundaries/watched frequencies",
                         "'" + prm.get("watched frequencies") + "': frequencies must be positive");
      c.watched_frequencies.push_back(f);
    }
    prm.leave_subsection();
  }
  catch (const InputError& e)
  {
    throw InputError(path, e.what());
  }
  return c;
}
} // namespace chipflex::apps
