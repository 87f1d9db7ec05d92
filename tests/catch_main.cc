// Catch2's main for the test executables that need no MPI. The OpenMP threads spin only
// briefly at barriers, as in the chipflex command (common/openmp_waiting.h), so that the
// tests keep their pace on a machine that other jobs keep busy.
#define CATCH_CONFIG_RUNNER
#include "common/openmp_waiting.h"

#include <catch2/catch.hpp>

int main(int argc, char** argv)
{
  chipflex::spin_briefly_at_barriers(argv);
  return Catch::Session().run(argc, argv);
}
