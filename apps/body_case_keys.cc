#include "apps/body_case_keys.h"

#include "apps/body_kinds/body_kind.h"
#include "common/input_error.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <deal.II/base/parameter_handler.h>
#include <limits>
#include <map>
#include <regex>

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
/// Every kind-specific key with its default, and which keys each kind uses.
struct KindKeys
{
  std::vector<std::pair<std::string, std::string>> defaults;
  std::map<std::string, std::vector<std::string>> used_by_kind;
};

void declare_common(ParameterHandler& prm)
{
  std::string kinds = "none", doc = "none";
  for (const BodyKind* k : body_kinds())
  {
    kinds += "|" + k->name();
    doc += ", " + k->description();
  }
  prm.declare_entry("kind", "none", Selection(kinds), doc + ".");
  prm.declare_entry("name", "", Anything(), "Name in outputs; empty: body<N>.");
  prm.declare_entry("wall model", "automatic",
                    Selection("automatic|lennard jones|dummy particles|thin skin"),
                    "How the fluid feels the skin. thin skin: sided dummy particles that keep "
                    "the fluid on the skin's two sides apart, for a skin of any thickness "
                    "down to zero (docs/sph.md, \"Thin skins\"); automatic: thin skin where "
                    "the skin is open or thinner than 2h - dp (the fluid on its two sides "
                    "would interact through it), else lennard jones.");
  prm.declare_entry("lennard jones k", "0", Double(0),
                    "Wall force scale per unit mass, m/s^2; 0: derived as for fixed walls.");
  prm.declare_entry("lennard jones R", "0", Double(0), "Cut-off, m; 0: dp.");
  prm.declare_entry("lennard jones r0", "0", Double(0), "Equilibrium distance, m; 0: dp/2.");
  prm.declare_entry("position", "", Anything(),
                    "Where the body's frame origin goes, m (2 or 3 numbers; empty: 0). rigid "
                    "primitives: their centre; chain: the clamp (top hinge); flexible, mesh and "
                    "moving wall: the origin of the file's coordinates; sph solid: the centre "
                    "of the clamped end.");
  prm.declare_entry("rotation axis", "0, 0, 1", Anything(),
                    "3D: the axis of the initial rotation by `angle` (any length).");
  prm.declare_entry("angle", "0", Double(), "Initial rotation of the frame, rad.");
  prm.declare_entry("clamped", "true", Bool(),
                    "rigid: fixed in space; flexible: frame clamped to ground.");
  prm.declare_entry("velocity", "", Anything(),
                    "Initial velocity of a free body's frame (moving wall: its constant "
                    "velocity), m/s; empty: 0.");
  prm.declare_entry("angular velocity", "", Anything(),
                    "Initial angular velocity of a free body, world axes (2D: one number "
                    "about z; moving wall: its constant rotation about its origin), rad/s.");
  prm.declare_entry("implicit", "true", Bool(),
                    "Body integrator: generalised alpha (true) or symplectic Euler (false).");
  prm.declare_entry("rho infinity", "0.9", Double(0, 1), "Generalised-alpha spectral radius, -.");
  prm.declare_entry("max step", "0", Double(0),
                    "Body sub-step limit within a fluid step, s; 0: one step per fluid step.");
  prm.declare_entry("weight", "true", Bool(),
                    "Whether gravity (the fluid's) acts on the body; false: a weightless body "
                    "(the fluid still loads it).");
  prm.declare_entry("probe point", "", Anything(),
                    "m (2 or 3 numbers): the probe (displacement output, RMS) is the skin node "
                    "nearest to this point at the start; empty: the kind's probe point.");
}

KindKeys declare_kinds(ParameterHandler& prm)
{
  KindKeys keys;
  for (const BodyKind* k : body_kinds())
  {
    BodyKeyDeclarations d(prm, k->name(), &keys.defaults);
    k->declare(d);
  }
  // Which kind uses which key (shared keys are declared once above): each kind alone.
  for (const BodyKind* k : body_kinds())
  {
    ParameterHandler scratch;
    std::vector<std::pair<std::string, std::string>> alone;
    BodyKeyDeclarations d(scratch, k->name(), &alone);
    k->declare(d);
    for (const auto& entry : alone)
      keys.used_by_kind[k->name()].push_back(entry.first);
  }
  return keys;
}
} // namespace
int count_body_subsections(const std::string& text)
{
  static const std::regex body(R"(^\s*subsection\s+body\s+([0-9]+)\s*$)");
  int highest = 0;
  std::size_t start = 0;
  while (start < text.size())
  {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos)
      end = text.size();
    std::smatch m;
    const std::string line = text.substr(start, end - start);
    if (std::regex_match(line, m, body))
      highest = std::max(highest, std::stoi(m[1]));
    start = end + 1;
  }
  return highest;
}

void declare_body_keys(ParameterHandler& prm, int n_bodies)
{
  prm.enter_subsection("bodies");
  prm.declare_entry("count", "0", Integer(0),
                    "Number of bodies, declared in `subsection body 1` ... `body N`; 0: every "
                    "body subsection of the file.");
  for (int b = 1; b <= std::max(1, n_bodies); ++b)
  {
    prm.enter_subsection("body " + std::to_string(b));
    declare_common(prm);
    declare_kinds(prm);
    prm.leave_subsection();
  }
  declare_chip_source_keys(prm);
  prm.leave_subsection();
}

int n_case_bodies(ParameterHandler& prm, int declared)
{
  prm.enter_subsection("bodies");
  int count = int(prm.get_integer("count"));
  if (count == 0)
    for (int b = 1; b <= declared; ++b)
    {
      prm.enter_subsection("body " + std::to_string(b));
      if (prm.get("kind") != "none")
        count = b;
      prm.leave_subsection();
    }
  prm.leave_subsection();
  if (count > declared)
    throw InputError("bodies, count", "count = " + std::to_string(count) +
                                          " but the highest body subsection is body " +
                                          std::to_string(declared));
  return count;
}

template <int dim>
BodyCase<dim> read_body_case(ParameterHandler& prm, const std::string& case_path,
                             const sph::CaseDescription<dim>& fluid, int declared)
{
  const int count = n_case_bodies(prm, declared);
  ParameterHandler scratch;
  const KindKeys kind_keys = declare_kinds(scratch);
  BodyCase<dim> c;
  prm.enter_subsection("bodies");
  for (int b = 1; b <= count; ++b)
  {
    const std::string where = case_path + ": bodies, body " + std::to_string(b);
    prm.enter_subsection("body " + std::to_string(b));
    const std::string kind_name = prm.get("kind");
    if (kind_name == "none")
      throw InputError(where + ", kind", "count = " + std::to_string(count) + " but body " +
                                             std::to_string(b) + " has kind none");
    const BodyKind& kind = body_kind(kind_name, where + ", kind");
    BodyKeys keys(prm, where, case_path);
    // A key of another kind set to anything but its default is a mistake.
    const auto& own = kind_keys.used_by_kind.at(kind_name);
    for (const auto& [key, default_value] : kind_keys.defaults)
      if (std::find(own.begin(), own.end(), key) == own.end() && prm.get(key) != default_value)
        throw InputError(keys.at(key), "does not apply to a body of kind " + kind_name);

    BodyContext<dim> context;
    context.name = prm.get("name").empty() ? "body" + std::to_string(b) : prm.get("name");
    context.where = where;
    context.case_path = case_path;
    context.gravity = fluid.fluid.gravity;
    context.rotating_frame = fluid.fluid.rotating_frame;
    if (!keys.flag("weight"))
      context.gravity.setZero();
    context.particle_spacing = fluid.fluid.particle_spacing;
    auto& p = context.placement;
    p.position = keys.vector<dim>("position");
    const double angle = keys.number("angle");
    if constexpr (dim == 2)
      p.rotation = Eigen::Rotation2Dd(angle).toRotationMatrix();
    else
    {
      const Eigen::Vector3d axis = keys.vector<3>("rotation axis");
      if (!(axis.norm() > 0))
        throw InputError(keys.at("rotation axis"), "must not be the zero vector");
      p.rotation = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
    }
    p.velocity = keys.vector<dim>("velocity");
    if constexpr (dim == 2)
    {
      const auto w = keys.numbers("angular velocity");
      if (w.size() > 1)
        throw InputError(keys.at("angular velocity"), "2D: one number (about z)");
      p.angular_velocity[2] = w.empty() ? 0 : w[0];
    }
    else
      p.angular_velocity = keys.vector<3>("angular velocity");
    p.clamped = keys.flag("clamped");
    context.integrator.scheme = keys.flag("implicit")
                                    ? mbs::IntegratorOptions::Scheme::generalized_alpha
                                    : mbs::IntegratorOptions::Scheme::symplectic_euler;
    context.integrator.rho_infinity = keys.number("rho infinity");
    context.max_step = keys.number("max step");

    CaseBody<dim> body;
    body.name = context.name;
    body.kind = kind_name;
    const std::string model = prm.get("wall model");
    body.automatic_wall_model = model == "automatic";
    body.wall_model = model == "dummy particles" ? sph::WallModel::dummy_particles
                      : model == "thin skin"     ? sph::WallModel::thin_skin
                                                 : sph::WallModel::lennard_jones;
    body.lennard_jones = {keys.number("lennard jones k"), keys.number("lennard jones R"),
                          keys.number("lennard jones r0")};
    for (const auto& other : c.bodies)
      if (other.name == body.name)
        throw InputError(keys.at("name"), "two bodies are called '" + body.name + "'");
    try
    {
      body.body = kind.build(keys, context);
    }
    catch (const InputError& e)
    {
      // The kind's own key checks name the place already; the rest (a file, a shape) get it.
      if (std::string(e.what()).rfind(case_path, 0) == 0)
        throw;
      throw InputError(where, e.what());
    }
    if (prm.get("probe point").find_first_not_of(" \t") != std::string::npos)
    {
      using Vector = Eigen::Matrix<double, dim, 1>;
      const Vector point = keys.vector<dim>("probe point");
      std::vector<Vector> x;
      body.body->skin().skin_positions(x);
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < x.size(); ++k)
        if ((x[k] - point).norm() < best)
        {
          best = (x[k] - point).norm();
          body.probe_node = static_cast<int>(k);
        }
    }
    c.bodies.push_back(std::move(body));
    prm.leave_subsection();
  }
  c.chip_source = read_chip_source_keys<dim>(prm, case_path + ": bodies, chip source",
                                             fluid.fluid.rotating_frame);
  prm.leave_subsection();
  return c;
}

template BodyCase<2> read_body_case(ParameterHandler&, const std::string&,
                                    const sph::CaseDescription<2>&, int);
template BodyCase<3> read_body_case(ParameterHandler&, const std::string&,
                                    const sph::CaseDescription<3>&, int);
} // namespace chipflex::apps
