// The `chipflex` command: one executable, one subcommand per job.

#include "apps/commands.h"
#include "common/input_error.h"
#include "common/openmp_waiting.h"

#include <cstring>
#include <functional>
#include <iostream>

namespace
{
struct Subcommand
{
  const char* name;
  const char* summary;
  std::function<int(const chipflex::apps::Arguments&)> run;
};

const Subcommand subcommands[] = {
    {"mesh", "generate a gmsh mesh of a gate, plate or chip", chipflex::apps::mesh_command},
    {"reduce", "reduce a mesh to a floating-frame body file (HDF5)",
     chipflex::apps::reduce_command},
    {"info", "summarise a body file", chipflex::apps::info_command},
    {"compare", "compare a reduced body against the full FE model",
     chipflex::apps::compare_command},
    {"run", "run an SPH (and coupled body) case", chipflex::apps::run_command},
    {"simulate", "integrate a reduced body on its own under a load history",
     chipflex::apps::simulate_command},
    {"bench", "run a benchmark and print its figures", chipflex::apps::bench_command},
    {"plot", "plot gate results against experiment (PNG)", chipflex::apps::plot_command},
    {"export", "export a body as an FMI 2.0 FMU or as SID", chipflex::apps::export_command},
};

void print_usage(std::ostream& out)
{
  out << "usage: chipflex SUBCOMMAND [options]   (chipflex SUBCOMMAND --help for details)\n\n"
         "subcommands:\n";
  for (const auto& s : subcommands)
    out << "  " << s.name << std::string(10 - std::strlen(s.name), ' ') << s.summary << "\n";
}
} // namespace

int main(int argc, char** argv)
{
  chipflex::spin_briefly_at_barriers(argv); // common/openmp_waiting.h
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h"))
  {
    print_usage(argc < 2 ? std::cerr : std::cout);
    return argc < 2 ? 2 : 0;
  }
  const chipflex::apps::Arguments args(argv + 2, argv + argc);
  for (const auto& s : subcommands)
    if (s.name == std::string(argv[1]))
    {
      try
      {
        return s.run(args);
      }
      catch (const chipflex::InputError& e)
      {
        std::cerr << "chipflex " << s.name << ": error: " << e.what() << "\n";
        return 2;
      }
      catch (const chipflex::SimulationError& e)
      {
        std::cerr << "chipflex " << s.name << ": stopped: " << e.what() << "\n";
        return 3;
      }
      catch (const std::exception& e)
      {
        std::cerr << "chipflex " << s.name << ": internal error: " << e.what() << "\n";
        return 1;
      }
    }
  std::cerr << "chipflex: unknown subcommand '" << argv[1] << "'\n";
  print_usage(std::cerr);
  return 2;
}
