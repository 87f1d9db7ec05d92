// export_matrices(): M and K of an assembled ElasticBody as files (fem/matrix_export.h,
// docs/export_matrices.md).

#include "fem/matrix_export.h"

#include "common/atomic_output.h"
#include "common/hdf5_file.h"
#include "common/input_error.h"

#include <cstdint>
#include <fstream>
#include <iomanip>
#include <sys/stat.h>

namespace chipflex::fem
{
namespace
{
/// One matrix's lower triangle over the unconstrained DoFs, in CSR order: rows ascending,
/// columns ascending within a row (PETSc's row order), 0-based, explicit zeros dropped.
struct LowerTriangle
{
  std::vector<std::int64_t> row_offsets{0}, columns;
  std::vector<double> values;
};

LowerTriangle lower_triangle(const PETScWrappers::MPI::SparseMatrix& matrix,
                             const std::vector<long>& row_of_dof)
{
  LowerTriangle t;
  for (std::size_t d = 0; d < row_of_dof.size(); ++d)
  {
    if (row_of_dof[d] < 0)
      continue;
    for (auto it = matrix.begin(d); it != matrix.end(d); ++it)
    {
      const long column = row_of_dof[it->column()];
      if (column >= 0 && column <= row_of_dof[d] && it->value() != 0)
      {
        t.columns.push_back(column);
        t.values.push_back(it->value());
      }
    }
    t.row_offsets.push_back(t.columns.size());
  }
  return t;
}

void write_matrix_market(const LowerTriangle& t, const std::string& path, const std::string& name)
{
  const std::size_t n_rows = t.row_offsets.size() - 1;
  AtomicOutput output(path);
  {
    std::ofstream out(output.temporary_path());
    out << "%%MatrixMarket matrix coordinate real symmetric\n"
        << "% chipflex " << name << ": clamped DoFs eliminated; row -> node: dof_nodes.csv\n"
        << n_rows << " " << n_rows << " " << t.values.size() << "\n"
        << std::setprecision(17);
    for (std::size_t r = 0; r < n_rows; ++r)
      for (auto k = t.row_offsets[r]; k < t.row_offsets[r + 1]; ++k)
        out << r + 1 << " " << t.columns[k] + 1 << " " << t.values[k] << "\n";
    if (!out)
      throw InputError(path, "cannot write");
  }
  output.commit();
}
} // namespace

MatrixExportFormat parse_matrix_export_format(const std::string& text, const std::string& option)
{
  if (text == "mtx")
    return MatrixExportFormat::matrix_market;
  if (text == "hdf5")
    return MatrixExportFormat::hdf5;
  throw InputError(option, "expected mtx or hdf5, got '" + text + "'");
}

template <int dim>
void export_matrices(const ElasticBody<dim>& body, const std::string& directory,
                     MatrixExportFormat format)
{
  if (body.n_processes != 1)
    throw InputError("--export-matrices", "runs on one process only");
  ::mkdir(directory.c_str(), 0755); // an existing folder is fine; a missing one fails below
  // Rows: the DoFs the clamp leaves free, in DoF order (not node order).
  const auto n_dofs = body.dof_handler.n_dofs();
  std::vector<long> row_of_dof(n_dofs, -1);
  long n_rows = 0;
  for (types::global_dof_index d = 0; d < n_dofs; ++d)
    if (!body.constraints.is_constrained(d))
      row_of_dof[d] = n_rows++;
  std::vector<std::int64_t> node(n_rows), component(n_rows);
  for (std::size_t k = 0; k < body.dof_of_node.size(); ++k)
    if (const long r = row_of_dof[body.dof_of_node[k]]; r >= 0)
    {
      node[r] = k / dim;
      component[r] = k % dim;
    }
  const LowerTriangle m = lower_triangle(body.mass_matrix, row_of_dof);
  const LowerTriangle k = lower_triangle(body.stiffness_matrix, row_of_dof);

  if (format == MatrixExportFormat::matrix_market)
  {
    write_matrix_market(m, directory + "/M.mtx", "M.mtx");
    write_matrix_market(k, directory + "/K.mtx", "K.mtx");
    const std::string path = directory + "/dof_nodes.csv";
    AtomicOutput output(path);
    {
      std::ofstream out(output.temporary_path());
      out << "row,node,component\n";
      for (long r = 0; r < n_rows; ++r)
        out << r + 1 << "," << node[r] << "," << component[r] << "\n";
      if (!out)
        throw InputError(path, "cannot write");
    }
    output.commit();
    return;
  }

  const std::string path = directory + "/matrices.h5";
  AtomicOutput output(path);
  {
    Hdf5File h5(output.temporary_path(), Hdf5File::Mode::create);
    h5.ensure_group("/meta");
    h5.write_attribute("/meta", "format_version", std::int64_t(1));
    h5.write_attribute("/meta", "dim", std::int64_t(dim));
    h5.write_attribute("/meta", "n_rows", std::int64_t(n_rows));
    h5.write_attribute("/meta", "storage", std::string("lower triangle, CSR, 0-based"));
    for (const auto& [name, t] : {std::pair{"M", &m}, std::pair{"K", &k}})
    {
      const std::string group = std::string("/") + name;
      h5.ensure_group(group);
      h5.write(group + "/row_offsets", t->row_offsets, {t->row_offsets.size()});
      h5.write(group + "/columns", t->columns, {t->columns.size()});
      h5.write(group + "/values", t->values, {t->values.size()});
    }
    h5.ensure_group("/rows");
    h5.write("/rows/node", node, {node.size()});
    h5.write("/rows/component", component, {component.size()});
  }
  output.commit();
}

template void export_matrices<2>(const ElasticBody<2>&, const std::string&, MatrixExportFormat);
template void export_matrices<3>(const ElasticBody<3>&, const std::string&, MatrixExportFormat);
} // namespace chipflex::fem
