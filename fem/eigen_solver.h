#pragma once
// The generalised symmetric eigenproblem K phi = lambda M phi (lambda = omega^2) for the
// eigenvalues nearest a target: SLEPc Krylov-Schur with shift-and-invert, the shifted
// matrix K - target M factorised by MUMPS (Cholesky/LDL^T). Options prefix `chipflex_`
// lets a user tune it from PETSc's options (e.g. -chipflex_eps_view, -log_view).

#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <vector>

namespace chipflex::fem
{
struct EigenSolution
{
  std::vector<double> eigenvalues;                         ///< ascending, omega^2
  std::vector<dealii::PETScWrappers::MPI::Vector> vectors; ///< M-normalised
  double factorisation_seconds = 0, solve_seconds = 0;
};

/// The `count` eigenpairs nearest `target` (relative residual tolerance 1e-8).
/// `node_block_size`: see MumpsCholesky (fem/direct_solver.h).
EigenSolution solve_eigenproblem(const dealii::PETScWrappers::MPI::SparseMatrix& stiffness,
                                 const dealii::PETScWrappers::MPI::SparseMatrix& mass,
                                 unsigned int count, double target,
                                 const dealii::PETScWrappers::MPI::Vector& layout,
                                 unsigned int node_block_size);
} // namespace chipflex::fem
