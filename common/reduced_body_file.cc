#include "common/reduced_body_file.h"

#include "common/atomic_output.h"
#include "common/hdf5_file.h"
#include "common/input_error.h"
#include "common/polynomial_stiffness.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace chipflex
{
namespace
{
using Shape = std::vector<std::size_t>;

std::vector<double> row_major(const Eigen::MatrixXd& m)
{
  std::vector<double> data(m.size());
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      data.data(), m.rows(), m.cols()) = m;
  return data;
}

Eigen::MatrixXd from_row_major(const std::vector<double>& data, std::size_t rows, std::size_t cols)
{
  return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      data.data(), rows, cols);
}

/// Stacks equally sized matrices into one row-major block of shape (count, r, c).
std::vector<double> stack(const std::vector<Eigen::MatrixXd>& blocks)
{
  std::vector<double> data;
  for (const auto& b : blocks)
  {
    const auto d = row_major(b);
    data.insert(data.end(), d.begin(), d.end());
  }
  return data;
}

std::vector<Eigen::MatrixXd> unstack(const std::vector<double>& data, std::size_t count,
                                     std::size_t r, std::size_t c)
{
  std::vector<Eigen::MatrixXd> blocks;
  for (std::size_t i = 0; i < count; ++i)
    blocks.push_back(from_row_major(
        std::vector<double>(data.begin() + i * r * c, data.begin() + (i + 1) * r * c), r, c));
  return blocks;
}

std::vector<std::int64_t> to_int64(const std::vector<int>& v)
{
  return std::vector<std::int64_t>(v.begin(), v.end());
}

/// Reads a dataset and checks its shape; `what` explains the expectation in the error.
std::vector<double> read_checked(const Hdf5File& file, const std::string& name,
                                 const Shape& expected)
{
  Shape shape;
  auto data = file.read_doubles(name, &shape);
  if (shape != expected)
  {
    std::ostringstream s;
    s << "shape (";
    for (std::size_t i = 0; i < shape.size(); ++i)
      s << (i ? "," : "") << shape[i];
    s << ") does not match the expected (";
    for (std::size_t i = 0; i < expected.size(); ++i)
      s << (i ? "," : "") << expected[i];
    s << ")";
    throw InputError(file.path() + ":" + name, s.str());
  }
  return data;
}

std::vector<int> read_ids(const Hdf5File& file, const std::string& name, int n_nodes)
{
  Shape shape;
  const auto raw = file.read_integers(name, &shape);
  if (shape.size() > 2)
    throw InputError(file.path() + ":" + name, "expected a list of node ids");
  std::vector<int> ids;
  ids.reserve(raw.size());
  for (auto id : raw)
  {
    if (id < 0 || id >= n_nodes)
      throw InputError(file.path() + ":" + name, "node id " + std::to_string(id) + " outside 0.." +
                                                     std::to_string(n_nodes - 1));
    ids.push_back(static_cast<int>(id));
  }
  return ids;
}
} // namespace

void write_reduced_body(const std::string& path, const ReducedBodyData& b)
{
  const std::size_t dim = b.dim, n = b.n_nodes(), m = b.n_modes();
  if ((b.dim != 2 && b.dim != 3) || b.nodes.cols() != b.dim ||
      static_cast<std::size_t>(b.psi.rows()) != dim * n)
    throw std::logic_error("write_reduced_body: inconsistent body data");

  AtomicOutput output(path);
  {
    Hdf5File f(output.temporary_path(), Hdf5File::Mode::create);
    f.write_attribute("/meta", "format_version", std::int64_t(ReducedBodyData::format_version));
    f.write_attribute("/meta", "dim", std::int64_t(b.dim));
    f.write_attribute("/meta", "youngs_modulus", b.youngs_modulus);
    f.write_attribute("/meta", "poisson_ratio", b.poisson_ratio);
    f.write_attribute("/meta", "density", b.density);
    f.write_attribute("/meta", "model", b.model);
    f.write_attribute("/meta", "mesh_file", b.mesh_file);
    f.write_attribute("/meta", "mesh_hash", b.mesh_hash);
    f.write_attribute("/meta", "element_degree", std::int64_t(b.element_degree));
    f.write_attribute("/meta", "clamp_set", b.clamp_set);
    f.write_attribute("/meta", "tool_version", b.tool_version);

    f.write("/mesh/nodes", row_major(b.nodes), {n, dim});
    f.write("/mesh/skin/node_ids", to_int64(b.skin_nodes), {b.skin_nodes.size()});
    std::vector<std::int64_t> faces(b.skin_faces.size());
    Eigen::Map<Eigen::Matrix<std::int64_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        faces.data(), b.skin_faces.rows(), b.skin_faces.cols()) = b.skin_faces.cast<std::int64_t>();
    f.write("/mesh/skin/faces", faces,
            {std::size_t(b.skin_faces.rows()), std::size_t(b.skin_faces.cols())});
    f.ensure_group("/mesh/sets");
    for (const auto& [name, ids] : b.node_sets)
      f.write("/mesh/sets/" + name, to_int64(ids), {ids.size()});

    f.write("/modes/psi", row_major(b.psi), {dim * n, m});
    f.write("/modes/frequencies_hz",
            std::vector<double>(b.frequencies_hz.data(), b.frequencies_hz.data() + m), {m});
    f.write("/modes/kinds", b.mode_kinds);

    f.write("/reduced/mass", row_major(b.mass_matrix), {m, m});
    f.write("/reduced/stiffness", row_major(b.stiffness_matrix), {m, m});

    f.write("/inertia/mass", std::vector<double>{b.mass}, {1});
    f.write("/inertia/center_of_mass",
            std::vector<double>(b.center_of_mass.data(), b.center_of_mass.data() + dim), {dim});
    f.write("/inertia/inertia_tensor", row_major(b.inertia_tensor), {3, 3});
    f.write("/inertia/c_xx", row_major(b.c_xx), {dim, dim});
    f.write("/inertia/translation_coupling", row_major(b.translation_coupling), {dim, m});
    f.write("/inertia/c_x_psi", stack(b.c_x_psi), {m, dim, dim});
    f.write("/inertia/c_psi_psi", stack(b.c_psi_psi), {m, m, dim, dim});
    if (b.nonlinear())
    {
      if (b.quadratic_stiffness.size() != n_sorted_triples(m) ||
          b.cubic_stiffness.size() != n_sorted_quadruples(m))
        throw std::logic_error("write_reduced_body: nonlinear coefficients do not match the modes");
      f.write_attribute("/nonlinear", "model", std::string("st_venant_kirchhoff"));
      f.write_attribute("/nonlinear", "n_modal_derivatives", std::int64_t(b.n_modal_derivatives));
      f.write("/nonlinear/quadratic", b.quadratic_stiffness, {b.quadratic_stiffness.size()});
      f.write("/nonlinear/cubic", b.cubic_stiffness, {b.cubic_stiffness.size()});
    }
  }
  output.commit();
}

ReducedBodyData read_reduced_body(const std::string& path)
{
  Hdf5File f(path, Hdf5File::Mode::read);
  ReducedBodyData b;
  const auto version = f.read_integer_attribute("/meta", "format_version");
  if (version != 1 && version != 2)
    throw InputError(path + ":/meta@format_version",
                     "version " + std::to_string(version) + " is not supported (expected 1 or 2)");
  b.file_version = static_cast<int>(version);
  b.dim = static_cast<int>(f.read_integer_attribute("/meta", "dim"));
  if (b.dim != 2 && b.dim != 3)
    throw InputError(path + ":/meta@dim", "must be 2 or 3, found " + std::to_string(b.dim));
  b.youngs_modulus = f.read_double_attribute("/meta", "youngs_modulus");
  b.poisson_ratio = f.read_double_attribute("/meta", "poisson_ratio");
  b.density = f.read_double_attribute("/meta", "density");
  b.model = f.read_string_attribute("/meta", "model");
  b.mesh_file = f.read_string_attribute("/meta", "mesh_file");
  b.mesh_hash = f.read_string_attribute("/meta", "mesh_hash");
  b.element_degree = static_cast<int>(f.read_integer_attribute("/meta", "element_degree"));
  b.clamp_set = f.read_string_attribute("/meta", "clamp_set");
  b.tool_version = f.read_string_attribute("/meta", "tool_version");

  Shape shape;
  const auto nodes = f.read_doubles("/mesh/nodes", &shape);
  if (shape.size() != 2 || shape[1] != std::size_t(b.dim) || shape[0] == 0)
    throw InputError(path + ":/mesh/nodes", "expected an (n_nodes x dim) array");
  const std::size_t n = shape[0], dim = b.dim;
  b.nodes = from_row_major(nodes, n, dim);

  b.skin_nodes = read_ids(f, "/mesh/skin/node_ids", n);
  Shape face_shape;
  f.read_integers("/mesh/skin/faces", &face_shape);
  if (face_shape.size() != 2 || face_shape[1] != dim)
    throw InputError(path + ":/mesh/skin/faces", "expected an (n_faces x dim) array");
  const auto faces = read_ids(f, "/mesh/skin/faces", n);
  b.skin_faces.resize(face_shape[0], dim);
  for (std::size_t i = 0; i < face_shape[0]; ++i)
    for (std::size_t j = 0; j < dim; ++j)
      b.skin_faces(i, j) = faces[i * dim + j];
  for (const auto& name : f.children("/mesh/sets"))
    b.node_sets[name] = read_ids(f, "/mesh/sets/" + name, n);

  Shape psi_shape;
  const auto psi = f.read_doubles("/modes/psi", &psi_shape);
  if (psi_shape.size() != 2 || psi_shape[0] != dim * n)
    throw InputError(path + ":/modes/psi", "expected (dim * n_nodes) rows");
  const std::size_t m = psi_shape[1];
  b.psi = from_row_major(psi, dim * n, m);
  b.frequencies_hz =
      Eigen::Map<const Eigen::VectorXd>(read_checked(f, "/modes/frequencies_hz", {m}).data(), m);
  b.mode_kinds = f.read_strings("/modes/kinds");
  if (b.mode_kinds.size() != m)
    throw InputError(path + ":/modes/kinds", "expected one kind per mode");

  b.mass_matrix = from_row_major(read_checked(f, "/reduced/mass", {m, m}), m, m);
  b.stiffness_matrix = from_row_major(read_checked(f, "/reduced/stiffness", {m, m}), m, m);

  b.mass = read_checked(f, "/inertia/mass", {1})[0];
  if (!(b.mass > 0))
    throw InputError(path + ":/inertia/mass", "must be positive");
  b.center_of_mass = Eigen::Map<const Eigen::VectorXd>(
      read_checked(f, "/inertia/center_of_mass", {dim}).data(), dim);
  b.inertia_tensor = from_row_major(read_checked(f, "/inertia/inertia_tensor", {3, 3}), 3, 3);
  b.c_xx = from_row_major(read_checked(f, "/inertia/c_xx", {dim, dim}), dim, dim);
  b.translation_coupling =
      from_row_major(read_checked(f, "/inertia/translation_coupling", {dim, m}), dim, m);
  b.c_x_psi = unstack(read_checked(f, "/inertia/c_x_psi", {m, dim, dim}), m, dim, dim);
  b.c_psi_psi = unstack(read_checked(f, "/inertia/c_psi_psi", {m, m, dim, dim}), m * m, dim, dim);
  if (version >= 2 && f.exists("/nonlinear"))
  {
    const auto model = f.read_string_attribute("/nonlinear", "model");
    if (model != "st_venant_kirchhoff")
      throw InputError(path + ":/nonlinear@model", "unknown model '" + model + "'");
    b.n_modal_derivatives =
        static_cast<int>(f.read_integer_attribute("/nonlinear", "n_modal_derivatives"));
    if (b.n_modal_derivatives < 0 || b.n_modal_derivatives > static_cast<int>(m))
      throw InputError(path + ":/nonlinear@n_modal_derivatives", "outside 0..number of modes");
    b.quadratic_stiffness = read_checked(f, "/nonlinear/quadratic", {n_sorted_triples(m)});
    b.cubic_stiffness = read_checked(f, "/nonlinear/cubic", {n_sorted_quadruples(m)});
  }
  return b;
}

std::string file_hash(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path, "cannot open file");
  std::uint64_t hash = 1469598103934665603ull;
  char buffer[65536];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
  {
    for (std::streamsize i = 0; i < in.gcount(); ++i)
    {
      hash ^= static_cast<unsigned char>(buffer[i]);
      hash *= 1099511628211ull;
    }
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}
} // namespace chipflex
