#pragma once
// Wall-clock seconds for the timings that reduce, compare and the benchmarks report.

#include <chrono>

namespace chipflex
{
using WallClock = std::chrono::steady_clock;

/// Seconds elapsed since `start`.
inline double seconds_since(WallClock::time_point start)
{
  return std::chrono::duration<double>(WallClock::now() - start).count();
}
} // namespace chipflex
