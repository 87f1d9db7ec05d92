#pragma once
// A sparse direct solver for A = c_k K + c_m M, factorised once (MUMPS Cholesky/LDL^T through
// PETSc) and reused for any number of right-hand sides: static modes, static responses,
// and every Newmark step of the full model. PETSc's own LU is far too slow in 3D.

#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <petscksp.h>

namespace chipflex::fem
{
class DirectSolver
{
public:
  /// Factorises c_k K + c_m M now. Options prefix `chipflex_direct_`.
  DirectSolver(double c_k, const dealii::PETScWrappers::MPI::SparseMatrix& stiffness, double c_m,
               const dealii::PETScWrappers::MPI::SparseMatrix& mass);
  ~DirectSolver();
  DirectSolver(const DirectSolver&) = delete;
  DirectSolver& operator=(const DirectSolver&) = delete;

  void solve(const dealii::PETScWrappers::MPI::Vector& rhs,
             dealii::PETScWrappers::MPI::Vector& solution) const;

private:
  Mat matrix = nullptr;
  KSP ksp = nullptr;
};
} // namespace chipflex::fem
