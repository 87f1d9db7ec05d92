#include "apps/body_xdmf.h"

#include "apps/surface_output.h"
#include "common/atomic_output.h"
#include "common/hdf5_file.h"
#include "common/input_error.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace chipflex::apps
{
namespace
{
namespace fs = std::filesystem;

std::string data_item(const std::string& dims, const char* type, const std::string& path)
{
  return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + type +
         "\" Precision=\"8\" Format=\"HDF\">" + path + "</DataItem>";
}

/// Only what XML attribute values cannot hold as they are.
std::string xml_escaped(const std::string& s)
{
  std::string out;
  for (const char c : s)
    switch (c)
    {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    default:
      out += c;
    }
  return out;
}

/// The heavy data's path, checked before anything is written so that a bad path gives
/// one line and no file.
std::string checked_h5_path(const std::string& body_path, const std::string& xdmf_path)
{
  const std::string where = "--xdmf " + xdmf_path;
  const fs::path xdmf(xdmf_path);
  if (xdmf.extension() != ".xdmf" && xdmf.extension() != ".xmf")
    throw InputError(where, "expected a file name ending in .xdmf");
  std::error_code ec;
  if (fs::is_directory(xdmf, ec))
    throw InputError(where, "is a folder");
  const fs::path folder = xdmf.parent_path().empty() ? fs::path(".") : xdmf.parent_path();
  if (!fs::is_directory(folder, ec))
    throw InputError(where, "no folder '" + folder.string() + "'");
  if (::access(folder.c_str(), W_OK) != 0)
    throw InputError(where, "cannot write into '" + folder.string() + "'");
  fs::path h5 = xdmf;
  h5.replace_extension(".modes.h5");
  if (fs::exists(h5, ec) && fs::equivalent(h5, fs::path(body_path), ec))
    throw InputError(where, "its data file " + h5.string() + " would overwrite the body file");
  return h5.string();
}
} // namespace

std::string mode_array_name(int k, double frequency_hz)
{
  // A rigid-body mode's round-off frequency (1e-7 Hz) reads 0, which also keeps '-' out.
  char f[32];
  std::snprintf(f, sizeof f, "%.4g", std::abs(frequency_hz) < 1e-3 ? 0.0 : frequency_hz);
  std::string name = "mode_" + std::to_string(k) + "_";
  for (const char* c = f; *c; ++c)
    if (*c != '+') // 1.2e+05 -> 1.2e05: ParaView's calculator reads '+' as an operator
      name += *c;
  return name + "_Hz";
}

void write_body_xdmf(const ReducedBodyData& body, const std::string& body_path,
                     const std::string& xdmf_path)
{
  const std::string h5_path = checked_h5_path(body_path, xdmf_path);
  const int dim = body.dim;
  const std::size_t n = std::size_t(body.n_nodes()), n_faces = std::size_t(body.skin_faces.rows());
  const int m = body.n_modes();
  // Mass-normalised (psi^T M psi = 1): q is in sqrt(kg), psi in m per sqrt(kg).
  const std::string unit = dim == 2 ? "m/sqrt(kg/m)" : "m/sqrt(kg)";

  {
    AtomicOutput out(h5_path);
    {
      Hdf5File h5(out.temporary_path(), Hdf5File::Mode::create);
      h5.write_attribute("/", "body_file", body_path);
      h5.write_attribute("/", "dim", std::int64_t(dim));
      std::vector<double> nodes(3 * n, 0.0);
      for (std::size_t i = 0; i < n; ++i)
        for (int d = 0; d < dim; ++d)
          nodes[3 * i + d] = body.nodes(i, d);
      h5.write("/nodes", nodes, {n, 3});
      h5.write_attribute("/nodes", "unit", std::string("m"));
      std::vector<std::int64_t> faces(n_faces * dim);
      for (std::size_t f = 0; f < n_faces; ++f)
        for (int d = 0; d < dim; ++d)
          faces[f * dim + d] = body.skin_faces(f, d);
      h5.write("/faces", faces, {n_faces, std::size_t(dim)});
      std::vector<double> frequencies(m);
      for (int k = 0; k < m; ++k)
      {
        std::vector<double> shape(3 * n, 0.0);
        for (std::size_t i = 0; i < n; ++i)
          for (int d = 0; d < dim; ++d)
            shape[3 * i + d] = body.psi(i * dim + d, k);
        const std::string set = "/mode_" + std::to_string(k + 1);
        h5.write(set, shape, {n, 3});
        h5.write_attribute(set, "unit", unit);
        h5.write_attribute(set, "frequency_hz", body.frequencies_hz[k]);
        h5.write_attribute(set, "kind", body.mode_kinds[k]);
        frequencies[k] = body.frequencies_hz[k];
      }
      h5.write("/frequencies_hz", frequencies, {std::size_t(m)});
      h5.write("/mode_kinds", body.mode_kinds);
    }
    out.commit();
  }

  // The XDMF names the data file relative to itself, as ParaView resolves it.
  const std::string file = fs::path(h5_path).filename().string() + ":/";
  const std::string nodes = std::to_string(n) + " 3";
  AtomicOutput out(xdmf_path);
  {
    std::ofstream x(out.temporary_path());
    x.precision(17);
    x << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
         "<Xdmf Version=\"2.0\">\n <Domain>\n"
      << "  <Grid Name=\"" << surface_name(fs::path(body_path).stem().string())
      << "\" GridType=\"Uniform\">\n"
      << "   <Information Name=\"body_file\" Value=\"" << xml_escaped(body_path) << "\"/>\n"
      << "   <Topology TopologyType=\"" << (dim == 2 ? "Polyline" : "Triangle")
      << "\" NumberOfElements=\"" << n_faces << "\" NodesPerElement=\"" << dim << "\">"
      << data_item(std::to_string(n_faces) + " " + std::to_string(dim), "Int", file + "faces")
      << "</Topology>\n"
      << "   <Geometry GeometryType=\"XYZ\">" << data_item(nodes, "Float", file + "nodes")
      << "</Geometry>\n";
    for (int k = 0; k < m; ++k)
      x << "   <Attribute Name=\"" << mode_array_name(k + 1, body.frequencies_hz[k])
        << "\" AttributeType=\"Vector\" Center=\"Node\">"
        << "<Information Name=\"unit\" Value=\"" << unit << "\"/>"
        << "<Information Name=\"frequency_Hz\" Value=\"" << body.frequencies_hz[k] << "\"/>"
        << "<Information Name=\"kind\" Value=\"" << xml_escaped(body.mode_kinds[k]) << "\"/>"
        << data_item(nodes, "Float", file + "mode_" + std::to_string(k + 1)) << "</Attribute>\n";
    x << "  </Grid>\n </Domain>\n</Xdmf>\n";
    if (!x)
      throw InputError("--xdmf " + xdmf_path, "cannot write");
  }
  out.commit();
}
} // namespace chipflex::apps
