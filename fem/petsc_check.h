#pragma once
// Turns a PETSc/SLEPc error code into an exception naming the call.

#include <petscsys.h>
#include <stdexcept>
#include <string>

#define CHIPFLEX_PETSC_CHECK(call)                                                                 \
  do                                                                                               \
  {                                                                                                \
    const PetscErrorCode chipflex_petsc_error = (call);                                            \
    if (chipflex_petsc_error != 0)                                                                 \
      throw std::runtime_error(std::string("PETSc/SLEPc call failed (code ") +                     \
                               std::to_string(chipflex_petsc_error) + "): " + #call);              \
  } while (false)
