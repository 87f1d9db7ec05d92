#pragma once
// A sparse direct solver for A = c_k K + c_m M, factorised once (MUMPS Cholesky/LDL^T through
// PETSc) and reused for any number of right-hand sides: static modes, static responses,
// and every Newmark step of the full model. PETSc's own LU is far too slow in 3D.

#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <petscksp.h>
#include <string>

namespace chipflex::fem
{
/// Makes `pc` a MUMPS Cholesky/LDL^T factorisation, for as long as this object lives
/// (create it before the factorisation, let it go after). With `node_block_size` k > 1 the
/// DoFs come in aligned blocks of k (a node's components) and MUMPS orders the k-times
/// smaller graph of blocks (ICNTL(15) = -k): on `chipflex bench reduce` its analysis takes
/// half the time for the same factor size. SLEPc sets the operators of its solver late,
/// so this goes through the options database, as `-<prefix>mat_mumps_icntl_15 -k`, unless
/// the user has given that option; the entry is removed again on destruction.
class MumpsCholesky
{
public:
  MumpsCholesky(PC pc, unsigned int node_block_size);
  ~MumpsCholesky();
  MumpsCholesky(const MumpsCholesky&) = delete;
  MumpsCholesky& operator=(const MumpsCholesky&) = delete;

private:
  std::string option_set; ///< the option this object added, empty if none
};

class DirectSolver
{
public:
  /// Factorises c_k K + c_m M now. Options prefix `chipflex_direct_`.
  /// `node_block_size`: see MumpsCholesky.
  DirectSolver(double c_k, const dealii::PETScWrappers::MPI::SparseMatrix& stiffness, double c_m,
               const dealii::PETScWrappers::MPI::SparseMatrix& mass, unsigned int node_block_size);
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
