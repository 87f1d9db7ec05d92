#pragma once
// Creating the PETSc matrices of the FE system from a deal.II sparsity pattern, fast.
//
// deal.II 9.4's PETScWrappers::MPI::SparseMatrix::reinit(..., DynamicSparsityPattern, ...)
// preallocates and then inserts every row's pattern with MatSetValues: for the 350k-DoF
// quadratic hexahedral strip of `chipflex bench reduce` (131 M entries) that took 5 s per
// matrix, half of the whole setup. Handing PETSc the CSR arrays at once
// (MatMPIAIJSetPreallocationCSR) costs one pass over the pattern, and the second matrix
// of the same pattern is a structural copy (deal.II's reinit(other): MatDuplicate).

#include <deal.II/base/index_set.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/petsc_sparse_matrix.h>

namespace chipflex::fem
{
/// Makes `matrix` an MPI AIJ matrix over `communicator` with the rows `owned` (one
/// contiguous range per process, as PETSc requires) and exactly the entries of the
/// locally owned rows of `pattern` (already distributed), all zero. Inserting outside
/// the pattern is an error (MAT_NEW_NONZERO_ALLOCATION_ERR).
void reinit_from_pattern(dealii::PETScWrappers::MPI::SparseMatrix& matrix,
                         const dealii::DynamicSparsityPattern& pattern,
                         const dealii::IndexSet& owned, MPI_Comm communicator);
} // namespace chipflex::fem
