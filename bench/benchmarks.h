#pragma once
// Benchmarks print figures; they never pass or fail on time. `chipflex bench NAME`.
// One file per benchmark in bench/, registered in apps/bench_command.cc.

#include <string>
#include <vector>

namespace chipflex::bench
{
using Arguments = std::vector<std::string>;

/// Reduction of a ~350k-DOF quadratic 3D cantilever strip to 20 modes (bench/reduce_benchmark.cc).
int reduce_benchmark(const Arguments& args);
/// DualSPHysics' CaseDambreakVal2D to t = 0.05 s (bench/sph_dambreak_benchmark.cc).
int sph_dambreak2d_benchmark(const Arguments& args);
/// DualSPHysics' CaseDambreak (3D, with its column) to t = 0.02 s (same file).
int sph_dambreak3d_benchmark(const Arguments& args);
/// Wall time per implicit step: 20-mode 3D flexible body, 3-link chain
/// (bench/mbs_step_benchmark.cc).
int mbs_step_benchmark(const Arguments& args);
} // namespace chipflex::bench
