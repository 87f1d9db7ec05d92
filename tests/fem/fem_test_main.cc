// Catch2 main for the fem tests: PETSc/SLEPc (through deal.II) need MPI initialised once
// per process, before any test and finalised after all of them.
#define CATCH_CONFIG_RUNNER
#include "common/openmp_waiting.h"

#include <catch2/catch.hpp>
#include <deal.II/base/mpi.h>

int main(int argc, char** argv)
{
  chipflex::spin_briefly_at_barriers(argv); // before MPI starts
  // PETSc must not see Catch's options: it gets the program name only.
  int petsc_argc = 1;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(petsc_argc, argv, 1);
  return Catch::Session().run(argc, argv);
}
