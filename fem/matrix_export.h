#pragma once
// `chipflex reduce --export-matrices DIR`: the assembled M and K for other codes (e.g. to
// check modes against another eigen solver). What the files hold, and how their rows map to
// the body file's rows: docs/export_matrices.md.

#include "fem/elastic_body.h"

#include <string>

namespace chipflex::fem
{
enum class MatrixExportFormat
{
  matrix_market, ///< DIR/M.mtx, DIR/K.mtx (coordinate, real symmetric), DIR/dof_nodes.csv
  hdf5           ///< DIR/matrices.h5: both matrices as CSR datasets and the row -> node map
};

/// "mtx" or "hdf5" (the option's values); throws InputError naming `option` otherwise.
MatrixExportFormat parse_matrix_export_format(const std::string& text, const std::string& option);

/// Writes the lower triangles of M and K with the clamped DoFs' rows and columns left out,
/// rows in DoF order, and which node and component each row is. One process only.
template <int dim>
void export_matrices(const ElasticBody<dim>& body, const std::string& directory,
                     MatrixExportFormat format);
} // namespace chipflex::fem
