// `chipflex info BODY.h5 [--json] [--xdmf OUT.xdmf]`: what a body file holds, for people
// and for scripts, and its mesh with the mode shapes for ParaView.

#include "apps/body_xdmf.h"
#include "apps/commands.h"
#include "apps/json_value.h"
#include "common/command_line.h"
#include "common/reduced_body_file.h"

#include <iomanip>
#include <iostream>
#include <sstream>

namespace chipflex::apps
{
namespace
{
void print_json(const ReducedBodyData& b)
{
  std::ostringstream o;
  o << "{\n";
  o << "  \"format_version\": " << b.file_version << ",\n";
  o << "  \"elastic_model\": " << json_string(b.nonlinear() ? "nonlinear" : "linear") << ",\n";
  o << "  \"n_modal_derivatives\": " << b.n_modal_derivatives << ",\n";
  o << "  \"n_nonlinear_coefficients\": " << b.quadratic_stiffness.size() + b.cubic_stiffness.size()
    << ",\n";
  o << "  \"dim\": " << b.dim << ",\n";
  o << "  \"model\": " << json_string(b.model) << ",\n";
  o << "  \"youngs_modulus\": " << json_number(b.youngs_modulus) << ",\n";
  o << "  \"poisson_ratio\": " << json_number(b.poisson_ratio) << ",\n";
  o << "  \"density\": " << json_number(b.density) << ",\n";
  o << "  \"element_degree\": " << b.element_degree << ",\n";
  o << "  \"mesh_file\": " << json_string(b.mesh_file) << ",\n";
  o << "  \"mesh_hash\": " << json_string(b.mesh_hash) << ",\n";
  o << "  \"clamp_set\": " << json_string(b.clamp_set) << ",\n";
  o << "  \"mass\": " << json_number(b.mass) << ",\n";
  o << "  \"center_of_mass\": " << json_array(b.center_of_mass, b.dim) << ",\n";
  o << "  \"inertia\": [";
  for (int i = 0; i < 3; ++i)
    o << (i ? ", " : "") << json_array(b.inertia_tensor.row(i), 3);
  o << "],\n";
  o << "  \"n_modes\": " << b.n_modes() << ",\n";
  o << "  \"frequencies_hz\": " << json_array(b.frequencies_hz, b.n_modes()) << ",\n";
  o << "  \"mode_kinds\": [";
  for (int k = 0; k < b.n_modes(); ++k)
    o << (k ? ", " : "") << json_string(b.mode_kinds[k]);
  o << "],\n";
  o << "  \"n_nodes\": " << b.n_nodes() << ",\n";
  o << "  \"n_skin_nodes\": " << b.skin_nodes.size() << ",\n";
  o << "  \"n_skin_faces\": " << b.skin_faces.rows() << ",\n";
  o << "  \"node_sets\": {";
  bool first = true;
  for (const auto& [name, ids] : b.node_sets)
  {
    o << (first ? "" : ", ") << json_string(name) << ": " << ids.size();
    first = false;
  }
  o << "}\n}\n";
  std::cout << o.str();
}

void print_text(const std::string& path, const ReducedBodyData& b)
{
  std::ostringstream o;
  o << std::setprecision(6);
  o << path << ": reduced floating-frame body, format v" << b.file_version << ", " << b.dim << "D "
    << b.model << (b.dim == 2 ? " (per metre of depth)" : "") << "\n";
  o << "  material     E = " << b.youngs_modulus << " Pa, nu = " << b.poisson_ratio
    << ", rho = " << b.density << " kg/m^3\n";
  o << "  mesh         " << b.mesh_file << " (hash " << b.mesh_hash << "), degree "
    << b.element_degree << ", " << b.n_nodes() << " nodes, " << b.skin_nodes.size()
    << " skin nodes, " << b.skin_faces.rows() << " skin faces\n";
  o << "  reference    " << (b.clamp_set.empty() ? "free-free" : "clamped at '" + b.clamp_set + "'")
    << "\n  node sets   ";
  for (const auto& [name, ids] : b.node_sets)
    o << " " << name << " (" << ids.size() << ")";
  o << "\n  mass         " << b.mass << (b.dim == 2 ? " kg/m" : " kg") << "\n";
  o << "  centre       " << b.center_of_mass.transpose() << " m\n";
  o << "  inertia      about the centre of mass, kg m^2" << (b.dim == 2 ? "/m" : "") << "\n";
  for (int i = 0; i < 3; ++i)
    o << "               " << b.inertia_tensor.row(i) << "\n";
  o << "  elasticity   "
    << (b.nonlinear() ? "nonlinear (St Venant-Kirchhoff, cubic in q: " +
                            std::to_string(b.quadratic_stiffness.size()) + " quadratic + " +
                            std::to_string(b.cubic_stiffness.size()) + " cubic coefficients)"
                      : std::string("linear (K_red q)"))
    << "\n";
  o << "  modes        " << b.n_modes() << " basis vectors";
  if (b.nonlinear())
    o << ", of which " << b.n_modal_derivatives << " modal derivatives";
  o << "\n";
  for (int k = 0; k < b.n_modes(); ++k)
    o << "    " << std::setw(3) << k + 1 << "  " << std::setw(12) << b.frequencies_hz[k] << " Hz  "
      << b.mode_kinds[k] << "\n";
  std::cout << o.str();
}
} // namespace

int info_command(const Arguments& args)
{
  common::CommandLine cl("chipflex info BODY.h5 [--json] [--xdmf OUT.xdmf]",
                         "Summarise a reduced body file.");
  cl.add_positional("BODY", "body file written by chipflex reduce");
  cl.add_flag("--json", "print one JSON object instead of text");
  cl.add_option("--xdmf", "OUT.xdmf",
                "also write the mesh (all nodes, the skin faces as cells) with every mode "
                "shape as a point vector array mode_K_F_Hz for ParaView: OUT.xdmf + "
                "OUT.modes.h5");
  if (!cl.parse(args))
    return 0;
  const std::string path = cl.get("BODY");
  const ReducedBodyData body = read_reduced_body(path);
  // Written before anything is printed: a bad path is one line on stderr and no output.
  if (cl.has("--xdmf"))
    write_body_xdmf(body, path, cl.get("--xdmf"));
  if (cl.flag("--json"))
    print_json(body);
  else
  {
    print_text(path, body);
    if (cl.has("--xdmf"))
      std::cout << "  written      " << cl.get("--xdmf") << " (" << body.n_modes()
                << " mode shapes on " << body.n_nodes() << " nodes)\n";
  }
  return 0;
}
} // namespace chipflex::apps
