#include "fem/direct_solver.h"

#include "fem/petsc_check.h"

namespace chipflex::fem
{
MumpsCholesky::MumpsCholesky(PC pc, unsigned int node_block_size)
{
  CHIPFLEX_PETSC_CHECK(PCSetType(pc, PCCHOLESKY));
  CHIPFLEX_PETSC_CHECK(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  if (node_block_size < 2)
    return;
  const char* prefix = nullptr;
  CHIPFLEX_PETSC_CHECK(PCGetOptionsPrefix(pc, &prefix));
  const std::string name = std::string("-") + (prefix ? prefix : "") + "mat_mumps_icntl_15";
  PetscBool given;
  CHIPFLEX_PETSC_CHECK(PetscOptionsHasName(nullptr, nullptr, name.c_str(), &given));
  if (given)
    return;
  CHIPFLEX_PETSC_CHECK(
      PetscOptionsSetValue(nullptr, name.c_str(), std::to_string(-int(node_block_size)).c_str()));
  option_set = name;
}

MumpsCholesky::~MumpsCholesky()
{
  if (!option_set.empty())
    PetscOptionsClearValue(nullptr, option_set.c_str());
}

DirectSolver::DirectSolver(double c_k, const dealii::PETScWrappers::MPI::SparseMatrix& stiffness,
                           double c_m, const dealii::PETScWrappers::MPI::SparseMatrix& mass,
                           unsigned int node_block_size)
{
  const Mat k = stiffness, m = mass;
  CHIPFLEX_PETSC_CHECK(MatDuplicate(k, MAT_COPY_VALUES, &matrix));
  if (c_k != 1)
    CHIPFLEX_PETSC_CHECK(MatScale(matrix, c_k));
  if (c_m != 0)
    CHIPFLEX_PETSC_CHECK(MatAXPY(matrix, c_m, m, SUBSET_NONZERO_PATTERN));
  CHIPFLEX_PETSC_CHECK(MatSetOption(matrix, MAT_SYMMETRIC, PETSC_TRUE));
  CHIPFLEX_PETSC_CHECK(KSPCreate(PetscObjectComm(reinterpret_cast<PetscObject>(k)), &ksp));
  CHIPFLEX_PETSC_CHECK(KSPSetOptionsPrefix(ksp, "chipflex_direct_"));
  CHIPFLEX_PETSC_CHECK(KSPSetOperators(ksp, matrix, matrix));
  CHIPFLEX_PETSC_CHECK(KSPSetType(ksp, KSPPREONLY));
  PC pc;
  CHIPFLEX_PETSC_CHECK(KSPGetPC(ksp, &pc));
  const MumpsCholesky mumps(pc, node_block_size);
  CHIPFLEX_PETSC_CHECK(KSPSetFromOptions(ksp));
  CHIPFLEX_PETSC_CHECK(KSPSetUp(ksp));
}

DirectSolver::~DirectSolver()
{
  KSPDestroy(&ksp);
  MatDestroy(&matrix);
}

void DirectSolver::solve(const dealii::PETScWrappers::MPI::Vector& rhs,
                         dealii::PETScWrappers::MPI::Vector& solution) const
{
  CHIPFLEX_PETSC_CHECK(KSPSolve(ksp, rhs, solution));
  KSPConvergedReason reason;
  CHIPFLEX_PETSC_CHECK(KSPGetConvergedReason(ksp, &reason));
  if (reason < 0)
    throw std::runtime_error("direct solve failed (KSP reason " + std::to_string(reason) + ")");
}
} // namespace chipflex::fem
