#pragma once
// Creating the PETSc matrices of the FE system from a deal.II sparsity pattern, fast.
//
// deal.II 9.4's PETScWrappers::MPI::SparseMatrix::reinit(..., DynamicSparsityPattern, ...)
// preallocates and then inserts every row's pattern with MatSetValues: for the 350k-DoF
// quadratic hexahedral strip of `chipflex bench reduce` (131 M entries) that took 5 s per
// matrix, half of the whole setup. Handing PETSc the CSR arrays at once
// (MatMPIAIJSetPreallocationCSR) costs one pass over the pattern. A matrix may keep only
// part of the pattern: the consistent mass matrix of vector elasticity couples equal
// components only, a third of the stiffness matrix's entries.

#include <deal.II/base/index_set.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <functional>

namespace chipflex::fem
{
/// Makes `matrix` an MPI AIJ matrix over `communicator` with the rows `owned` (one
/// contiguous range per process, as PETSc requires) and exactly the entries of the
/// locally owned rows of `pattern` (already distributed), all zero. Inserting outside
/// the pattern is an error (MAT_NEW_NONZERO_ALLOCATION_ERR). With `keep`, only the
/// entries (row, column) for which it is true.
void reinit_from_pattern(dealii::PETScWrappers::MPI::SparseMatrix& matrix,
                         const dealii::DynamicSparsityPattern& pattern,
                         const dealii::IndexSet& owned, MPI_Comm communicator,
                         const std::function<bool(dealii::types::global_dof_index,
                                                  dealii::types::global_dof_index)>& keep = {});
} // namespace chipflex::fem
