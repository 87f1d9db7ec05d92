#include "fem/petsc_matrix_setup.h"

#include "fem/petsc_check.h"

#include <stdexcept>
#include <vector>

namespace chipflex::fem
{
void reinit_from_pattern(dealii::PETScWrappers::MPI::SparseMatrix& matrix,
                         const dealii::DynamicSparsityPattern& pattern,
                         const dealii::IndexSet& owned, MPI_Comm communicator,
                         const std::function<bool(dealii::types::global_dof_index,
                                                  dealii::types::global_dof_index)>& keep)
{
  if (!owned.is_contiguous())
    throw std::logic_error("PETSc matrices need one contiguous range of rows per process");
  // A deal.II reinit with an empty pattern (nothing to insert: cheap) sets the wrapper's
  // layout and communicator; its PETSc object is then replaced.
  const dealii::DynamicSparsityPattern empty(owned.size(), owned.size(), owned);
  matrix.reinit(owned, owned, empty, communicator);
  Mat& petsc = matrix.petsc_matrix();
  CHIPFLEX_PETSC_CHECK(MatDestroy(&petsc));
  const auto n_local = owned.n_elements();
  const auto first = owned.n_elements() ? *owned.begin() : 0;
  std::vector<PetscInt> row_start(n_local + 1, 0), columns;
  std::size_t n_entries = 0;
  for (dealii::types::global_dof_index r = 0; r < n_local; ++r)
    n_entries += pattern.row_length(first + r);
  columns.reserve(keep ? n_entries / 2 : n_entries);
  for (dealii::types::global_dof_index r = 0; r < n_local; ++r)
  {
    for (auto entry = pattern.begin(first + r); entry != pattern.end(first + r); ++entry)
      if (!keep || keep(first + r, entry->column()))
        columns.push_back(entry->column());
    row_start[r + 1] = columns.size();
  }
  CHIPFLEX_PETSC_CHECK(MatCreate(communicator, &petsc));
  CHIPFLEX_PETSC_CHECK(MatSetSizes(petsc, n_local, n_local, owned.size(), owned.size()));
  CHIPFLEX_PETSC_CHECK(MatSetType(petsc, MATMPIAIJ));
  CHIPFLEX_PETSC_CHECK(
      MatMPIAIJSetPreallocationCSR(petsc, row_start.data(), columns.data(), nullptr));
  CHIPFLEX_PETSC_CHECK(MatSetOption(petsc, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
}
} // namespace chipflex::fem
