#include "fmu/body_variables.h"

#include <cstdint>
#include <cstdio>

namespace chipflex::fmu
{
namespace
{
const char* const axis[] = {"x", "y", "z"};
const char* const quaternion_axis[] = {"w", "x", "y", "z"};
} // namespace

void BodyVariables::add(Variable v)
{
  variables_.push_back(std::move(v));
}

BodyVariables::BodyVariables(const ReducedBodyData& body)
{
  const int dim = body.dim, rdim = dim == 2 ? 1 : 3, n_modes = body.n_modes();
  const int n_skin = static_cast<int>(body.skin_nodes.size());
  // 2D bodies are per metre of depth (docs/body_file_format.md).
  const std::string force_unit = dim == 2 ? "N/m" : "N", moment_unit = dim == 2 ? "N" : "N.m",
                    energy_unit = dim == 2 ? "J/m" : "J";
  const auto real = [](std::string name, Causality c, double start, Role role, int index,
                       int component, std::string unit, std::string description)
  {
    Variable v;
    v.name = std::move(name);
    v.causality = c;
    v.start = start;
    v.role = role;
    v.index = index;
    v.component = component;
    v.unit = std::move(unit);
    v.description = std::move(description);
    return v;
  };

  // ---- parameters
  {
    Variable v = real("clamped", Causality::parameter, body.clamp_set.empty() ? 0 : 1,
                      Role::clamped, 0, 0, "",
                      "frame fixed to ground at its initial pose (the body file's clamp set '" +
                          body.clamp_set + "' is then held)");
    v.type = VariableType::boolean;
    add(v);
  }
  add(real("step_size", Causality::parameter, 1e-4, Role::step_size, 0, 0, "s",
           "largest internal step of the generalised-alpha integrator; a communication step "
           "is split into equal steps not above it"));
  add(real("rho_infinity", Causality::parameter, 0.9, Role::rho_infinity, 0, 0, "",
           "generalised-alpha spectral radius at infinite frequency, 0..1"));
  {
    Variable v = real("damping", Causality::parameter, 0, Role::damping, 0, 0, "",
                      "modal damping: 0 none, 1 Rayleigh (alpha M + beta K), 2 modal (zeta)");
    v.type = VariableType::integer;
    add(v);
  }
  add(real("rayleigh_alpha", Causality::parameter, 0, Role::rayleigh_alpha, 0, 0, "1/s",
           "Rayleigh mass-proportional coefficient (damping = 1)"));
  add(real("rayleigh_beta", Causality::parameter, 0, Role::rayleigh_beta, 0, 0, "s",
           "Rayleigh stiffness-proportional coefficient (damping = 1)"));
  add(real("modal_damping_ratio", Causality::parameter, 0, Role::modal_damping_ratio, 0, 0, "",
           "damping ratio of every mode (damping = 2)"));
  for (int d = 0; d < dim; ++d)
    add(real(std::string("gravity.") + axis[d], Causality::parameter, 0, Role::gravity, 0, d,
             "m/s2", "gravitational acceleration, world axes"));
  for (int d = 0; d < dim; ++d)
    add(real(std::string("initial.position.") + axis[d], Causality::parameter, 0,
             Role::initial_position, 0, d, "m", "frame origin at the start, world axes"));
  if (dim == 2)
    add(real("initial.angle", Causality::parameter, 0, Role::initial_rotation, 0, 0, "rad",
             "frame angle at the start"));
  else
    for (int d = 0; d < dim; ++d)
      add(real(std::string("initial.rotation_vector.") + axis[d], Causality::parameter, 0,
               Role::initial_rotation, 0, d, "rad", "frame rotation at the start (axis * angle)"));

  // ---- inputs
  for (int d = 0; d < dim; ++d)
    add(real(std::string("frame.force.") + axis[d], Causality::input, 0, Role::frame_force, 0, d,
             force_unit, "force on the frame origin, world axes"));
  if (dim == 2)
    add(real("frame.moment", Causality::input, 0, Role::frame_moment, 0, 0, moment_unit,
             "moment about the frame origin (z)"));
  else
    for (int d = 0; d < dim; ++d)
      add(real(std::string("frame.moment.") + axis[d], Causality::input, 0, Role::frame_moment, 0,
               d, moment_unit, "moment about the frame origin, world axes"));
  for (const auto& [name, nodes] : body.node_sets)
  {
    if (nodes.empty())
      continue;
    const int index = static_cast<int>(set_names_.size());
    set_names_.push_back(name);
    for (int d = 0; d < dim; ++d)
      add(real("set." + name + ".force." + axis[d], Causality::input, 0, Role::set_force, index, d,
               force_unit,
               "total force on node set '" + name + "' (" + std::to_string(nodes.size()) +
                   " nodes), shared equally by its nodes, world axes"));
  }
  for (int i = 0; i < n_skin; ++i)
    for (int d = 0; d < dim; ++d)
      add(real("skin.force[" + std::to_string(i) + "]." + axis[d], Causality::input, 0,
               Role::skin_force, i, d, force_unit,
               "force on skin node " + std::to_string(i) + " (node " +
                   std::to_string(body.skin_nodes[i]) + "), world axes"));

  // ---- outputs
  for (int d = 0; d < dim; ++d)
    add(real(std::string("frame.position.") + axis[d], Causality::output, 0, Role::frame_position,
             0, d, "m", "frame origin, world axes"));
  if (dim == 2)
    add(real("frame.angle", Causality::output, 0, Role::frame_orientation, 0, 0, "rad",
             "frame angle (unwrapped)"));
  else
    for (int d = 0; d < 4; ++d)
      add(real(std::string("frame.quaternion.") + quaternion_axis[d], Causality::output, 0,
               Role::frame_orientation, 0, d, "", "frame orientation, unit quaternion"));
  for (int d = 0; d < dim; ++d)
    add(real(std::string("frame.velocity.") + axis[d], Causality::output, 0, Role::frame_velocity,
             0, d, "m/s", "frame origin velocity, world axes"));
  if (dim == 2)
    add(real("frame.angular_velocity", Causality::output, 0, Role::frame_angular_velocity, 0, 0,
             "rad/s", "frame angular velocity (z)"));
  else
    for (int d = 0; d < rdim; ++d)
      add(real(std::string("frame.angular_velocity.") + axis[d], Causality::output, 0,
               Role::frame_angular_velocity, 0, d, "rad/s", "frame angular velocity, body axes"));
  const std::string modal_unit = dim == 2 ? "sqrt(kg/m).m" : "sqrt(kg).m";
  for (int k = 0; k < n_modes; ++k)
    add(real("q[" + std::to_string(k) + "]", Causality::output, 0, Role::modal_coordinate, k, 0, "",
             "modal coordinate of mode " + std::to_string(k) + " (" + body.mode_kinds[k] +
                 ", mass-normalised, " + modal_unit + ")"));
  for (int k = 0; k < n_modes; ++k)
    add(real("q_dot[" + std::to_string(k) + "]", Causality::output, 0, Role::modal_velocity, k, 0,
             "", "modal velocity of mode " + std::to_string(k) + " (" + modal_unit + "/s)"));
  for (int i = 0; i < n_skin; ++i)
    for (int d = 0; d < dim; ++d)
      add(real("skin.position[" + std::to_string(i) + "]." + axis[d], Causality::output, 0,
               Role::skin_position, i, d, "m", "skin node position, world axes"));
  for (int i = 0; i < n_skin; ++i)
    for (int d = 0; d < dim; ++d)
      add(real("skin.velocity[" + std::to_string(i) + "]." + axis[d], Causality::output, 0,
               Role::skin_velocity, i, d, "m/s", "skin node velocity, world axes"));
  for (std::size_t s = 0; s < set_names_.size(); ++s)
    for (int d = 0; d < dim; ++d)
      add(real("set." + set_names_[s] + ".position." + axis[d], Causality::output, 0,
               Role::set_position, static_cast<int>(s), d, "m",
               "mean position of the nodes of set '" + set_names_[s] + "', world axes"));
  const std::string momentum_unit = dim == 2 ? "N.s/m" : "N.s";
  for (int d = 0; d < dim; ++d)
    add(real(std::string("linear_momentum.") + axis[d], Causality::output, 0, Role::linear_momentum,
             0, d, momentum_unit, "linear momentum of the body"));
  add(real("kinetic_energy", Causality::output, 0, Role::kinetic_energy, 0, 0, energy_unit,
           "kinetic energy of the body"));
  add(real("strain_energy", Causality::output, 0, Role::strain_energy, 0, 0, energy_unit,
           "strain energy 1/2 q^T K q"));

  // ---- constants: the skin's geometry
  const auto integer_constant = [&](std::string name, double value, Role role, int index,
                                    int component, std::string description)
  {
    Variable v = real(std::move(name), Causality::output, value, role, index, component, "",
                      std::move(description));
    v.type = VariableType::integer;
    v.constant = true;
    add(v);
  };
  for (int i = 0; i < n_skin; ++i)
    integer_constant("skin.node_id[" + std::to_string(i) + "]", body.skin_nodes[i],
                     Role::skin_node_id, i, 0,
                     "body file node id of skin node " + std::to_string(i));
  // Faces hold node ids; the FMU's faces hold skin node numbers (positions in skin_nodes).
  std::vector<int> skin_number(body.n_nodes(), -1);
  for (int i = 0; i < n_skin; ++i)
    skin_number[body.skin_nodes[i]] = i;
  for (int f = 0; f < body.skin_faces.rows(); ++f)
    for (int c = 0; c < dim; ++c)
      integer_constant("skin.face[" + std::to_string(f) + "][" + std::to_string(c) + "]",
                       skin_number[body.skin_faces(f, c)], Role::skin_face, f, c,
                       "corner " + std::to_string(c) + " of skin face " + std::to_string(f) +
                           " (skin node number; outward normal as in the body file)");
}

int BodyVariables::first(Role role) const
{
  for (std::size_t k = 0; k < variables_.size(); ++k)
    if (variables_[k].role == role)
      return static_cast<int>(k);
  return -1;
}

std::string body_guid(const std::string& bytes)
{
  // FNV-1a 64 with the standard offset basis, and again with the basis advanced over a
  // fixed prefix: two independent-looking 64-bit halves of a 128-bit GUID.
  const auto fnv = [&](std::uint64_t hash)
  {
    for (unsigned char c : bytes)
    {
      hash ^= c;
      hash *= 1099511628211ull;
    }
    return hash;
  };
  std::uint64_t basis2 = 1469598103934665603ull;
  for (unsigned char c : std::string("chipflex body FMU"))
  {
    basis2 ^= c;
    basis2 *= 1099511628211ull;
  }
  const std::uint64_t a = fnv(1469598103934665603ull), b = fnv(basis2);
  char guid[40];
  std::snprintf(guid, sizeof guid, "{%08x-%04x-%04x-%04x-%012llx}", unsigned(a >> 32),
                unsigned((a >> 16) & 0xffff), unsigned(a & 0xffff), unsigned(b >> 48),
                static_cast<unsigned long long>(b & 0xffffffffffffull));
  return guid;
}
} // namespace chipflex::fmu
