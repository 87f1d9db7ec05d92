#include "apps/bench_case.h"
#include "apps/commands.h"
#include "bench/benchmarks.h"
#include "common/input_error.h"

#include <functional>
#include <iostream>

namespace chipflex::apps
{
namespace
{
struct Benchmark
{
  const char* name;
  const char* summary;
  std::function<int(const Arguments&)> run;
};

const Benchmark benchmarks[] = {
    {"reduce", "reduce a ~350k-DOF quadratic 3D strip to 20 modes", bench::reduce_benchmark},
    {"sph-dambreak2d", "DualSPHysics CaseDambreakVal2D to t = 0.05 s",
     bench::sph_dambreak2d_benchmark},
    {"sph-dambreak3d", "DualSPHysics CaseDambreak (3D, with its column) to t = 0.02 s",
     bench::sph_dambreak3d_benchmark},
    {"mbs", "wall time per implicit step of a 20-mode body and a 3-link chain",
     bench::mbs_step_benchmark},
    {"case", "wall time per step of any case file (chipflex bench case CASE.prm --help)",
     bench_case},
};

void print_list(std::ostream& out)
{
  out << "usage: chipflex bench NAME [options]   (chipflex bench NAME --help)\n\nbenchmarks:\n";
  for (const auto& b : benchmarks)
    out << "  " << b.name << "\n      " << b.summary << "\n";
}
} // namespace

int bench_command(const Arguments& args)
{
  if (args.empty() || args[0] == "--help" || args[0] == "-h")
  {
    print_list(std::cout);
    return args.empty() ? 2 : 0;
  }
  for (const auto& b : benchmarks)
    if (args[0] == b.name)
      return b.run(Arguments(args.begin() + 1, args.end()));
  throw InputError("chipflex bench " + args[0], "unknown benchmark (chipflex bench --help)");
}
} // namespace chipflex::apps
