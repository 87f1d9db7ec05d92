// libFuzzer target: the body-file reader (common/reduced_body_file.cc) and the body built
// from what it accepts (mbs::FloatingFrameBody). Structure-aware: the input does not
// become the HDF5 file's bytes (that would fuzz libhdf5's own parser) but chooses, object
// by object, what a damaged or hand-made body file holds: the attributes present or
// missing, each dataset's shape (the body's dim, nodes and modes, or off by one) and its
// values (finite, NaN, infinite, negative, node ids out of range). Whatever the reader
// accepts must build a body and give finite-or-refused equations without a crash.
#include "common/hdf5_file.h"
#include "common/reduced_body_file.h"
#include "fuzz_input.h"
#include "mbs/floating_frame_body.h"

#include <cmath>
#include <exception>
#include <fuzzer/FuzzedDataProvider.h>
#include <limits>
#include <numeric>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
using chipflex::Hdf5File;

struct Writer
{
  FuzzedDataProvider& in;
  Hdf5File& file;

  bool skip() { return in.ConsumeIntegralInRange<int>(0, 15) == 0; }
  /// A size near `n`: usually n, sometimes off by one or zero.
  std::size_t size_near(std::size_t n)
  {
    switch (in.ConsumeIntegralInRange<int>(0, 7))
    {
    case 0:
      return n + 1;
    case 1:
      return n > 0 ? n - 1 : 0;
    case 2:
      return 0;
    default:
      return n;
    }
  }
  double value()
  {
    switch (in.ConsumeIntegralInRange<int>(0, 15))
    {
    case 0:
      return std::numeric_limits<double>::quiet_NaN();
    case 1:
      return std::numeric_limits<double>::infinity();
    case 2:
      return -1e300;
    case 3:
      return 0;
    default:
      return in.ConsumeFloatingPointInRange<double>(-2, 2);
    }
  }
  /// Each extent near its intended size; returns the number of entries.
  std::size_t perturb(std::vector<std::size_t>& shape)
  {
    for (auto& s : shape)
      s = size_near(s);
    return std::accumulate(shape.begin(), shape.end(), std::size_t(1),
                           std::multiplies<std::size_t>());
  }
  void doubles(const std::string& name, std::vector<std::size_t> shape)
  {
    if (skip())
      return;
    const std::size_t count = perturb(shape);
    std::vector<double> v(count);
    for (auto& x : v)
      x = value();
    file.write(name, v, shape);
  }
  void ids(const std::string& name, std::vector<std::size_t> shape, int range)
  {
    if (skip())
      return;
    const std::size_t count = perturb(shape);
    std::vector<std::int64_t> v(count);
    for (auto& x : v)
      x = in.ConsumeIntegralInRange<std::int64_t>(-2, range + 1);
    file.write(name, v, shape);
  }
  void attribute(const std::string& name, std::int64_t typical, std::int64_t lo, std::int64_t hi)
  {
    if (!skip())
      file.write_attribute("/meta", name,
                           in.ConsumeBool() ? typical : in.ConsumeIntegralInRange(lo, hi));
  }
  void attribute(const std::string& name, double typical)
  {
    if (!skip())
      file.write_attribute("/meta", name, in.ConsumeBool() ? typical : value());
  }
  void attribute(const std::string& name, const std::string& typical)
  {
    if (!skip())
      file.write_attribute("/meta", name,
                           in.ConsumeBool() ? typical : in.ConsumeRandomLengthString(16));
  }
};

template <int dim>
void build(const chipflex::ReducedBodyData& data)
{
  chipflex::mbs::FloatingFrameBody<dim> body(data);
  const int nv = body.n_velocities();
  Eigen::MatrixXd m(nv, nv);
  Eigen::VectorXd f(nv);
  body.mass_matrix(m);
  body.forces(Eigen::Matrix<double, dim, 1>::Zero(), f);
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  FuzzedDataProvider in(data, size);
  const std::string path = "/tmp/chipflex_fuzz_" + std::to_string(::getpid()) + ".h5";
  const int dim = in.ConsumeBool() ? 2 : 3;
  const std::size_t d = dim, n = in.ConsumeIntegralInRange<std::size_t>(1, 6);
  const std::size_t m = in.ConsumeIntegralInRange<std::size_t>(0, 4);
  try
  {
    {
      Hdf5File file(path, Hdf5File::Mode::create);
      Writer w{in, file};
      w.attribute("format_version", 2, -1, 3);
      w.attribute("dim", dim, -1, 4);
      w.attribute("youngs_modulus", 1e7);
      w.attribute("poisson_ratio", 0.3);
      w.attribute("density", 1000.0);
      w.attribute("model", dim == 2 ? "plane_strain" : "solid_3d");
      w.attribute("mesh_file", "body.msh");
      w.attribute("mesh_hash", "0123456789abcdef");
      w.attribute("element_degree", 2, -1, 4);
      w.attribute("clamp_set", in.ConsumeBool() ? "" : "clamp");
      w.attribute("tool_version", "chipflex fuzz");
      w.doubles("/mesh/nodes", {n, d});
      w.ids("/mesh/skin/node_ids", {n}, int(n));
      w.ids("/mesh/skin/faces", {n, d}, int(n));
      if (!w.skip())
        file.ensure_group("/mesh/sets");
      w.ids("/mesh/sets/clamp", {1}, int(n));
      w.doubles("/modes/psi", {d * n, m});
      w.doubles("/modes/frequencies_hz", {m});
      if (!w.skip())
      {
        std::vector<std::string> kinds;
        for (std::size_t k = 0; k < w.size_near(m); ++k)
          kinds.push_back(in.ConsumeBool() ? "normal" : in.ConsumeRandomLengthString(12));
        file.write("/modes/kinds", kinds);
      }
      w.doubles("/reduced/mass", {m, m});
      w.doubles("/reduced/stiffness", {m, m});
      w.doubles("/inertia/mass", {1});
      w.doubles("/inertia/center_of_mass", {d});
      w.doubles("/inertia/inertia_tensor", {3, 3});
      w.doubles("/inertia/c_xx", {d, d});
      w.doubles("/inertia/translation_coupling", {d, m});
      w.doubles("/inertia/c_x_psi", {m, d, d});
      w.doubles("/inertia/c_psi_psi", {m, m, d, d});
      if (in.ConsumeBool())
      {
        file.write_attribute("/nonlinear", "model",
                             in.ConsumeBool() ? std::string("st_venant_kirchhoff")
                                              : in.ConsumeRandomLengthString(8));
        file.write_attribute("/nonlinear", "n_modal_derivatives",
                             in.ConsumeIntegralInRange<std::int64_t>(-1, 5));
        const std::size_t q = m * (m + 1) * (m + 2) / 6, c = q * (m + 3) / 4;
        w.doubles("/nonlinear/quadratic", {q});
        w.doubles("/nonlinear/cubic", {c});
      }
    }
    const auto body = chipflex::read_reduced_body(path);
    if (body.dim == 2)
      build<2>(body);
    else
      build<3>(body);
  }
  catch (const std::exception&)
  {
  }
  std::remove(path.c_str());
  return 0;
}
