#include "fem/direct_solver.h"

#include "fem/petsc_check.h"

namespace chipflex::fem
{
DirectSolver::DirectSolver(double c_k, const dealii::PETScWrappers::MPI::SparseMatrix& stiffness,
                           double c_m, const dealii::PETScWrappers::MPI::SparseMatrix& mass)
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
  CHIPFLEX_PETSC_CHECK(PCSetType(pc, PCCHOLESKY));
  CHIPFLEX_PETSC_CHECK(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
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
