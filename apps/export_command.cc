// `chipflex export fmu|sid BODY.h5 -o FILE`: hands a reduced body to other tools.
//   fmu  an FMI 2.0 co-simulation FMU around chipflex's own floating-frame body and
//        integrator (fmu/, docs/export_fmu_sid.md), for any FMI importer
//   sid  the Standard Input Data of Wallrapp (1994) as a text file (.SID_FEM), for
//        multibody codes that read flexible bodies in that form (common/sid_writer.h)

#include "apps/commands.h"
#include "common/command_line.h"
#include "common/input_error.h"
#include "common/reduced_body_file.h"
#include "common/sid_writer.h"
#include "fmu/fmu_export.h"

#include <filesystem>
#include <iostream>
#include <unistd.h>

namespace chipflex::apps
{
namespace
{
/// libchipflex_fmi.so beside the build's bin/ folder: <bin>/../lib/.
std::string default_runtime()
{
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec)
    return "libchipflex_fmi.so";
  return (exe.parent_path().parent_path() / "lib" / "libchipflex_fmi.so").string();
}

int export_fmu_command(const Arguments& args)
{
  common::CommandLine cl(
      "chipflex export fmu BODY.h5 -o BODY.fmu [options]",
      "Pack a body file into an FMI 2.0 co-simulation FMU: chipflex's floating-frame\n"
      "body and generalised-alpha integrator as binaries/linux64/<id>.so, the body\n"
      "file as resources/body.h5. Inputs: forces on the frame, on node sets and on\n"
      "skin nodes; outputs: frame pose and velocities, modal coordinates, skin node\n"
      "positions and velocities (docs/export_fmu_sid.md).");
  cl.add_positional("BODY", "body file from chipflex reduce");
  cl.add_option("--output", "FMU", "the FMU to write");
  cl.add_alias("-o", "--output");
  cl.add_option("--model-identifier", "ID", "FMI modelIdentifier (a C identifier)",
                "chipflex_body");
  cl.add_option("--step", "S", "DefaultExperiment step size, s", "1e-4");
  cl.add_option("--stop-time", "T", "DefaultExperiment stop time, s", "0.1");
  cl.add_option("--runtime", "SO", "the FMU runtime library", default_runtime());
  if (!cl.parse(args))
    return 0;
  if (!cl.has("BODY") || !cl.has("--output"))
    throw InputError("chipflex export fmu", "needs BODY.h5 and -o BODY.fmu (--help)");
  fmu::FmuExportOptions options;
  options.runtime_library = cl.get("--runtime");
  options.model_identifier = cl.get("--model-identifier");
  options.default_step = cl.get_double("--step");
  options.default_stop = cl.get_double("--stop-time");
  const auto s = fmu::export_fmu(cl.get("BODY"), cl.get("--output"), options);
  std::cout << "wrote " << cl.get("--output") << ": FMI 2.0 co-simulation, GUID " << s.guid << ", "
            << s.n_variables << " variables (" << s.n_parameters << " parameters, " << s.n_inputs
            << " inputs, " << s.n_outputs << " outputs)\n";
  return 0;
}
int export_sid_command(const Arguments& args)
{
  common::CommandLine cl(
      "chipflex export sid BODY.h5 -o BODY.SID_FEM [options]",
      "Write the body's Standard Input Data (Wallrapp 1994) as text: refmod, the\n"
      "nodes' frame data (origin, phi), mdCM, J, Ct, Cr, Me, Gr, Ge, Oe, ksigma, Ke,\n"
      "De (docs/export_fmu_sid.md: which entries are filled, which are zero).");
  cl.add_positional("BODY", "body file from chipflex reduce");
  cl.add_option("--output", "SID", "the SID file to write");
  cl.add_alias("-o", "--output");
  cl.add_option("--nodes", "SET",
                "write only this node set of the body file to the frame section (default: all "
                "nodes)");
  if (!cl.parse(args))
    return 0;
  if (!cl.has("BODY") || !cl.has("--output"))
    throw InputError("chipflex export sid", "needs BODY.h5 and -o BODY.SID_FEM (--help)");
  const ReducedBodyData body = read_reduced_body(cl.get("BODY"));
  SidOptions options;
  if (cl.has("--nodes"))
  {
    const auto it = body.node_sets.find(cl.get("--nodes"));
    if (it == body.node_sets.end() || it->second.empty())
      throw InputError("--nodes " + cl.get("--nodes"),
                       "no such (non-empty) node set in " + cl.get("BODY"));
    options.nodes = it->second;
  }
  write_sid(cl.get("--output"), body, options);
  std::cout << "wrote " << cl.get("--output") << ": SID of " << body.n_modes() << " modes, "
            << (options.nodes.empty() ? body.n_nodes() : int(options.nodes.size()))
            << " nodes, mass " << body.mass << (body.dim == 2 ? " kg/m" : " kg") << "\n";
  return 0;
}
} // namespace

int export_command(const Arguments& args)
{
  const std::string usage = "chipflex export fmu|sid BODY.h5 -o FILE [options] (--help)";
  if (args.empty() || args[0] == "--help" || args[0] == "-h")
  {
    std::cout << "usage: " << usage
              << "\n\n  fmu  an FMI 2.0 co-simulation FMU of the body"
                 "\n  sid  the body's Standard Input Data (Wallrapp 1994), .SID_FEM text\n";
    if (args.empty())
      throw InputError("chipflex export", "needs fmu or sid (" + usage + ")");
    return 0;
  }
  const Arguments rest(args.begin() + 1, args.end());
  if (args[0] == "fmu")
    return export_fmu_command(rest);
  if (args[0] == "sid")
    return export_sid_command(rest);
  throw InputError("chipflex export " + args[0], "unknown format (fmu or sid)");
}
} // namespace chipflex::apps
