#pragma once
// One function per subcommand, each in its own file apps/<name>_command.cc.
// Each takes the arguments after the subcommand name and returns the exit status.

#include <string>
#include <vector>

namespace chipflex::apps
{
using Arguments = std::vector<std::string>;

int mesh_command(const Arguments& args);     // apps/mesh_command.cc
int reduce_command(const Arguments& args);   // apps/reduce_command.cc
int info_command(const Arguments& args);     // apps/info_command.cc
int compare_command(const Arguments& args);  // apps/compare_command.cc
int run_command(const Arguments& args);      // apps/run_command.cc
int simulate_command(const Arguments& args); // apps/simulate_command.cc
int bench_command(const Arguments& args);    // apps/bench_command.cc
int plot_command(const Arguments& args);     // apps/plot_command.cc
int export_command(const Arguments& args);   // apps/export_command.cc
} // namespace chipflex::apps
