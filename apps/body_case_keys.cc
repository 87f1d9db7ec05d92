#include "apps/body_case_keys.h"

#include "apps/case_file.h"
#include "common/input_error.h"

#include <deal.II/base/parameter_handler.h>
#include <filesystem>
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
constexpr int max_bodies = 4;

void declare_body(ParameterHandler& prm)
{
  prm.declare_entry("kind", "none", Selection("none|rigid|chain|flexible|sph solid|fmu"),
                    "none, rigid (box), chain (rigid links with torsion springs, Table 2), "
                    "flexible (reduced body file), sph solid (Gray et al. 2001 strip) or fmu "
                    "(an FMI 2.0 co-simulation FMU with skin variables).");
  prm.declare_entry("name", "", Anything(), "Name in outputs; empty: body<N>.");
  prm.declare_entry("wall model", "lennard jones", Selection("lennard jones|dummy particles"),
                    "How the fluid feels the skin.");
  prm.declare_entry("lennard jones k", "0", Double(0),
                    "Wall force scale per unit mass, m/s^2; 0: derived as for fixed walls.");
  prm.declare_entry("lennard jones R", "0", Double(0), "Cut-off, m; 0: dp.");
  prm.declare_entry("lennard jones r0", "0", Double(0), "Equilibrium distance, m; 0: dp/2.");
  prm.declare_entry("position", "0, 0", Anything(),
                    "m. rigid: box centre; chain: clamp (top hinge); flexible: where the body "
                    "file's origin goes; sph solid: centre of the clamped end.");
  prm.declare_entry("angle", "0", Double(), "Frame rotation (rigid, flexible), rad.");
  prm.declare_entry("clamped", "true", Bool(),
                    "rigid: fixed in space; flexible: frame clamped to ground.");
  prm.declare_entry("velocity", "0, 0", Anything(), "Initial velocity of a free body, m/s.");
  prm.declare_entry("implicit", "true", Bool(),
                    "Body integrator: generalised alpha (true) or symplectic Euler (false).");
  prm.declare_entry("rho infinity", "0.9", Double(0, 1), "Generalised-alpha spectral radius, -.");
  prm.declare_entry("max step", "0", Double(0),
                    "Body sub-step limit within a fluid step, s; 0: one step per fluid step.");
  prm.declare_entry("width", "0.05", Double(0), "Rigid box width, m.");
  prm.declare_entry("height", "0.05", Double(0), "Rigid box height, m.");
  prm.declare_entry("density", "1100", Double(0), "Rigid box, chain links, sph solid; kg/m^3.");
  prm.declare_entry("links", "1", Integer(1, 3), "Chain: 1, 2 or 3 links (Table 2).");
  prm.declare_entry("length", "0.079", Double(0), "Chain / sph solid strip length, m.");
  prm.declare_entry("thickness", "0.005", Double(0), "Chain / sph solid strip thickness, m.");
  prm.declare_entry("spring rate", "0", Double(0),
                    "Chain torsion springs, Nm/rad per metre; 0: Table 2.");
  prm.declare_entry("spring damping", "0", Double(0), "Chain, Nms/rad per metre.");
  prm.declare_entry("body file", "", Anything(), "Flexible: HDF5 file from `chipflex reduce`.");
  prm.declare_entry("fmu file", "", Anything(),
                    "Fmu: FMI 2.0 co-simulation FMU, e.g. from `chipflex export fmu`.");
  prm.declare_entry("modes", "-1", Integer(-1), "Flexible: first n modes of the file; -1: all.");
  prm.declare_entry("modal damping", "0", Double(0), "Flexible: damping ratio of every mode, -.");
  prm.declare_entry("rayleigh mass", "0", Double(0), "Flexible: Rayleigh alpha, 1/s.");
  prm.declare_entry("rayleigh stiffness", "0", Double(0), "Flexible: Rayleigh beta, s.");
  prm.declare_entry("probe set", "tip", Anything(),
                    "Flexible: node set whose mean is the probe (displacement output).");
  prm.declare_entry("clamp set", "clamp", Anything(),
                    "Flexible with large rotation: the node set at the clamped end.");
  prm.declare_entry("large rotation", "false", Bool(),
                    "Flexible, clamped beam: rebuild the skin inextensibly from the linear "
                    "rotation field (coupling/large_rotation_beam_skin.h), so that large "
                    "deflections foreshorten the beam.");
  prm.declare_entry("youngs modulus", "1.2e7", Double(0), "SPH solid: E, Pa (Table 1).");
  prm.declare_entry("poisson ratio", "0.4", Double(-1, 0.5), "SPH solid: nu, - (Table 1).");
  prm.declare_entry("artificial stress", "0.2", Double(0), "SPH solid: epsilon (Table 1).");
  prm.declare_entry("solid viscosity", "1", Double(0), "SPH solid: Monaghan alpha, -.");
  prm.declare_entry("spacing", "0.001", Double(0), "SPH solid: particle spacing along, m.");
  prm.declare_entry("layers", "6", Integer(2), "SPH solid: particles across the thickness.");
  prm.declare_entry("clamp rows", "4", Integer(1), "SPH solid: fixed rows beyond the clamp.");
  prm.declare_entry("clamp columns", "8", Integer(2), "SPH solid: fixed particles per row.");
  prm.declare_entry("smoothing factor", "1.3", Double(0), "SPH solid: h / spacing, -.");
  prm.declare_entry("direction", "0, -1", Anything(),
                    "SPH solid: unit vector from the clamped to the free end.");
}

Eigen::Vector2d read_vector(ParameterHandler& prm, const std::string& key, const std::string& where)
{
  std::stringstream s(prm.get(key));
  std::vector<double> v;
  std::string cell;
  while (std::getline(s, cell, ','))
  {
    try
    {
      v.push_back(std::stod(cell));
    }
    catch (const std::exception&)
    {
      throw InputError(where + ", " + key, "'" + prm.get(key) + "' is not a list of numbers");
    }
  }
  if (v.size() != 2)
    throw InputError(where + ", " + key, "'" + prm.get(key) +
                                             "': expected 2 numbers (a 2D vector), got " +
                                             std::to_string(v.size()));
  return {v[0], v[1]};
}

std::string locate(const std::string& file, const std::string& case_path, const std::string& where)
{
  namespace fs = std::filesystem;
  if (file.empty() || fs::path(file).is_absolute())
    return file;
  const fs::path beside = fs::path(case_path).parent_path() / file;
  if (fs::exists(beside))
    return beside.string();
  if (fs::exists(file))
    return file;
  throw InputError(where, "file '" + file + "' found neither beside " + case_path +
                              " nor in the working directory");
}
} // namespace

void declare_body_keys(ParameterHandler& prm)
{
  prm.enter_subsection("bodies");
  prm.declare_entry("count", "0", Integer(0, max_bodies),
                    "Number of bodies, declared in `subsection body 1` ... `body N`.");
  prm.declare_entry("reference", "", Anything(),
                    "CSV (time_s, dx_m, dy_m) the first body's probe displacement is compared "
                    "with (RMS in the summary), e.g. the Antoci experiment; empty: none.");
  prm.declare_entry("error window", "0.04, 0.36", Anything(),
                    "Reference frames inside [begin, end] enter the RMS error, s.");
  for (int b = 1; b <= max_bodies; ++b)
  {
    prm.enter_subsection("body " + std::to_string(b));
    declare_body(prm);
    prm.leave_subsection();
  }
  prm.leave_subsection();
}

BodyCase read_body_case(ParameterHandler& prm, const std::string& case_path)
{
  BodyCase c;
  prm.enter_subsection("bodies");
  const int count = prm.get_integer("count");
  const std::string reference = prm.get("reference");
  const Eigen::Vector2d window = read_vector(prm, "error window", case_path + ": bodies");
  for (int b = 1; b <= count; ++b)
  {
    prm.enter_subsection("body " + std::to_string(b));
    const std::string where = case_path + ": bodies, body " + std::to_string(b);
    if (prm.get("kind") == "none")
      throw InputError(where + ", kind", "count = " + std::to_string(count) + " but body " +
                                             std::to_string(b) + " has kind none");
    coupling::BodyDescription d;
    d.kind = coupling::parse_body_kind(prm.get("kind"), where + ", kind");
    d.name = prm.get("name").empty() ? "body" + std::to_string(b) : prm.get("name");
    d.wall_model = prm.get("wall model") == "lennard jones" ? sph::WallModel::lennard_jones
                                                            : sph::WallModel::dummy_particles;
    d.lennard_jones.k = prm.get_double("lennard jones k");
    d.lennard_jones.R = prm.get_double("lennard jones R");
    d.lennard_jones.r0 = prm.get_double("lennard jones r0");
    d.position = read_vector(prm, "position", where);
    d.angle = prm.get_double("angle");
    d.clamped = prm.get_bool("clamped");
    d.velocity = read_vector(prm, "velocity", where);
    d.implicit = prm.get_bool("implicit");
    d.rho_infinity = prm.get_double("rho infinity");
    d.max_step = prm.get_double("max step");
    d.width = prm.get_double("width");
    d.height = prm.get_double("height");
    d.density = prm.get_double("density");
    d.links = prm.get_integer("links");
    d.length = prm.get_double("length");
    d.thickness = prm.get_double("thickness");
    d.spring_rate = prm.get_double("spring rate");
    d.spring_damping = prm.get_double("spring damping");
    if (d.kind == coupling::BodyKind::flexible)
      d.body_file = locate(prm.get("body file"), case_path, where + ", body file");
    if (d.kind == coupling::BodyKind::fmu)
      d.fmu_file = locate(prm.get("fmu file"), case_path, where + ", fmu file");
    d.modes = prm.get_integer("modes");
    d.modal_damping = prm.get_double("modal damping");
    d.rayleigh_mass = prm.get_double("rayleigh mass");
    d.rayleigh_stiffness = prm.get_double("rayleigh stiffness");
    d.probe_set = prm.get("probe set");
    d.clamp_set = prm.get("clamp set");
    d.large_rotation = prm.get_bool("large rotation");
    d.solid.density = d.density;
    d.solid.youngs_modulus = prm.get_double("youngs modulus");
    d.solid.poisson_ratio = prm.get_double("poisson ratio");
    d.solid.artificial_stress = prm.get_double("artificial stress");
    d.solid.viscosity_alpha = prm.get_double("solid viscosity");
    d.solid_spacing = prm.get_double("spacing");
    d.solid_layers = prm.get_integer("layers");
    d.clamp_rows = prm.get_integer("clamp rows");
    d.clamp_columns = prm.get_integer("clamp columns");
    d.smoothing_factor = prm.get_double("smoothing factor");
    d.direction = read_vector(prm, "direction", where);
    if (!(d.direction.norm() > 0))
      throw InputError(where + ", direction", "must not be the zero vector");
    for (const auto& other : c.bodies)
      if (other.name == d.name)
        throw InputError(where + ", name", "two bodies are called '" + d.name + "'");
    c.bodies.push_back(d);
    prm.leave_subsection();
  }
  if (!reference.empty())
    c.reference_file = locate(reference, case_path, case_path + ": bodies, reference");
  c.error_window_begin = window[0];
  c.error_window_end = window[1];
  prm.leave_subsection();
  return c;
}
} // namespace chipflex::apps
