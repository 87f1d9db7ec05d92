#pragma once
// How OpenMP threads wait at barriers, set once per process before the runtime starts.
//
// GNU libgomp lets a thread that reaches a barrier spin for 300,000 iterations before it
// sleeps. On a machine that other processes keep busy, the spinning thread holds a core
// that the thread the barrier waits for needs: a gate run on 2 cores beside 2 other
// CPU-bound processes took 11 times its idle time. Waiting passively (OMP_WAIT_POLICY=
// passive) cured that but cost 10-30 % on an idle machine, where a short spin catches the
// next parallel region; 1,000 iterations keep the idle speed and take 1.5 times the idle
// time beside 2 busy processes (docs/performance.md, "A busy machine").
//
// The runtime reads its settings when it is loaded, before main(), so the process starts
// itself again with GOMP_SPINCOUNT set, unless the user has chosen a wait policy or a spin
// count. Call it first thing in main(), before MPI or any thread exists.

#include <cstdlib>
#include <unistd.h>

namespace chipflex
{
inline void spin_briefly_at_barriers(char** argv)
{
  if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT"))
    return; // the user's choice stands
  setenv("GOMP_SPINCOUNT", "1000", 1);
  execv("/proc/self/exe", argv);
  // Only reached when the exec fails (no /proc): run on with the runtime's default.
}
} // namespace chipflex
