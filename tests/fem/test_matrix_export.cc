// `reduce --export-matrices` read back (docs/export_matrices.md): the HDF5 CSR datasets and
// the Matrix Market files hold the same lower triangles, the clamped DoFs are left out, and
// the row -> (node, component) map is right: with it the body file's modes, restricted to
// the exported rows, are M-orthonormal and give K_red (Psi^T M Psi = 1, Psi^T K Psi = K_red,
// the defining properties of the reduced basis), which a wrong map or a lost entry breaks.
#include "common/hdf5_file.h"
#include "fem_test_support.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

using namespace chipflex;
using namespace chipflex::fem;
using namespace chipflex::fem::testing;

namespace
{
/// A symmetric matrix from its stored lower triangle.
Eigen::MatrixXd from_lower(long n, const std::vector<std::int64_t>& offsets,
                           const std::vector<std::int64_t>& columns,
                           const std::vector<double>& values)
{
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (long r = 0; r < n; ++r)
    for (auto k = offsets[r]; k < offsets[r + 1]; ++k)
    {
      REQUIRE(columns[k] <= r); // lower triangle only
      a(r, columns[k]) = a(columns[k], r) = values[k];
    }
  return a;
}

/// The same from a Matrix Market coordinate file (1-based, lower triangle).
Eigen::MatrixXd read_matrix_market(const std::string& path)
{
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line) && line[0] == '%')
  {
  }
  std::istringstream size(line);
  long n, n_columns, entries;
  size >> n >> n_columns >> entries;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  long r, c;
  double v;
  for (long k = 0; k < entries && in >> r >> c >> v; ++k)
    a(r - 1, c - 1) = a(c - 1, r - 1) = v;
  return a;
}
} // namespace

TEST_CASE("exported matrices: HDF5 CSR read back, rows map to the body file's modes", "[fem]")
{
  ReductionSettings s;
  s.material = {1.2e7, 0.4, 1100, false}; // the gate's rubber
  s.mesh_file = gate_mesh(0.005 / 2);
  s.clamp_group = "clamp";
  s.n_modes = 3;
  s.static_modes = {"force:tip:1,0"};
  s.export_directory = scratch("export_hdf5");
  s.export_format = "hdf5";
  const ReducedBodyData body = reduce_body(s);
  s.export_directory = scratch("export_mtx");
  s.export_format = "mtx";
  reduce_body(s);

  const Hdf5File h5(scratch("export_hdf5/matrices.h5"), Hdf5File::Mode::read);
  const long n = h5.read_integer_attribute("/meta", "n_rows");
  const int dim = body.dim;
  const long n_clamped = body.node_sets.at("clamp").size();
  CHECK(n == dim * (body.n_nodes() - n_clamped));
  Eigen::MatrixXd m, k;
  for (const char* name : {"M", "K"})
  {
    const std::string g = std::string("/") + name;
    const auto offsets = h5.read_integers(g + "/row_offsets");
    REQUIRE(static_cast<long>(offsets.size()) == n + 1);
    const auto columns = h5.read_integers(g + "/columns");
    const auto values = h5.read_doubles(g + "/values");
    REQUIRE(columns.size() == values.size());
    REQUIRE(offsets.back() == static_cast<std::int64_t>(values.size()));
    (name[0] == 'M' ? m : k) = from_lower(n, offsets, columns, values);
  }
  // The text export holds the very same numbers (17 significant digits round-trip).
  CHECK(read_matrix_market(scratch("export_mtx/M.mtx")) == m);
  CHECK(read_matrix_market(scratch("export_mtx/K.mtx")) == k);

  // Row r is psi's row node * dim + component; no clamped node has a row.
  const auto node = h5.read_integers("/rows/node");
  const auto component = h5.read_integers("/rows/component");
  REQUIRE(static_cast<long>(node.size()) == n);
  const auto& clamp = body.node_sets.at("clamp");
  Eigen::MatrixXd psi(n, body.n_modes());
  for (long r = 0; r < n; ++r)
  {
    CHECK_FALSE(std::binary_search(clamp.begin(), clamp.end(), node[r]));
    psi.row(r) = body.psi.row(node[r] * dim + component[r]);
  }
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(body.n_modes(), body.n_modes());
  CHECK((psi.transpose() * m * psi - identity).norm() < 1e-10);
  CHECK((psi.transpose() * k * psi - body.stiffness_matrix).norm() <
        1e-10 * body.stiffness_matrix.norm());

  // The CSV map says the same, with 1-based rows.
  std::ifstream csv(scratch("export_mtx/dof_nodes.csv"));
  std::string line;
  std::getline(csv, line);
  CHECK(line == "row,node,component");
  long rows = 0;
  while (std::getline(csv, line))
  {
    CHECK(line == std::to_string(rows + 1) + "," + std::to_string(node[rows]) + "," +
                      std::to_string(component[rows]));
    ++rows;
  }
  CHECK(rows == n);
}
