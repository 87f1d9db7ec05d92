#pragma once
// Shared by the fem tests: meshes in a temporary scratch folder and a one-call reduction.

#include "fem/reduce.h"
#include "meshes/block_mesher.h"

#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <system_error>
#include <unistd.h>

namespace chipflex::fem::testing
{
/// A folder of this test process's own under the system's temporary directory, removed when
/// the process ends: tests write neither into the source tree nor into whatever directory
/// they were started from (a run from the repository root once left a scratch folder there).
class ScratchFolder
{
public:
  ScratchFolder()
  {
    const auto base = std::filesystem::temp_directory_path();
    std::random_device random;
    for (;;) // a fresh name: pid and a random tag, so concurrent runs never share one
    {
      path = base / ("chipflex_fem_test_" + std::to_string(::getpid()) + "_" +
                     std::to_string(random() % 1000000));
      if (std::filesystem::create_directory(path))
        break;
    }
  }
  ~ScratchFolder()
  {
    std::error_code ignored; // nothing to do about a folder that cannot be removed at exit
    std::filesystem::remove_all(path, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  std::filesystem::path path;
};

/// `name` inside this process's scratch folder.
inline std::string scratch(const std::string& name)
{
  static const ScratchFolder folder;
  return (folder.path / name).string();
}

/// The Antoci gate (2D, x = thickness, y = length, clamp at the top) or its 3D plate.
inline std::string gate_mesh(double size, bool simplex = false, double depth = 0,
                             double length = 0.079, double thickness = 0.005)
{
  meshes::BlockMeshSpec spec;
  spec.dim = depth > 0 ? 3 : 2;
  spec.extent = {thickness, length, depth};
  spec.long_axis = 1;
  spec.clamp_at_max = true;
  spec.size = size;
  spec.simplex = simplex;
  const std::string path = scratch("gate_" + std::to_string(spec.dim) + "d_" +
                                   std::to_string(size) + (simplex ? "_tri" : "") + ".msh");
  meshes::write_block_mesh(spec, path);
  return path;
}

/// A 3D strip along x, clamp at x = 0: length x width (y) x thickness (z).
inline std::string strip_mesh(double length, double width, double thickness, double size,
                              bool simplex = false)
{
  meshes::BlockMeshSpec spec;
  spec.dim = 3;
  spec.extent = {length, width, thickness};
  spec.long_axis = 0;
  spec.clamp_at_max = false;
  spec.size = size;
  spec.simplex = simplex;
  const std::string path = scratch("strip_" + std::to_string(length) + "_" + std::to_string(width) +
                                   "_" + std::to_string(thickness) + "_" + std::to_string(size) +
                                   (simplex ? "_tet" : "") + ".msh");
  meshes::write_block_mesh(spec, path);
  return path;
}

/// Euler-Bernoulli cantilever: f_k = (beta_k L)^2 / (2 pi L^2) sqrt(EI / (rho A)).
inline double cantilever_frequency(int k, double e, double i, double rho, double a, double l)
{
  static const double beta_l[] = {1.8751040687, 4.6940911330, 7.8547574382};
  return beta_l[k] * beta_l[k] / (2 * M_PI * l * l) * std::sqrt(e * i / (rho * a));
}

/// Euler-Bernoulli free-free beam: beta L = 4.7300407449, 7.8532046241, ...
inline double free_free_frequency(int k, double e, double i, double rho, double a, double l)
{
  static const double beta_l[] = {4.7300407449, 7.8532046241, 10.9956078380};
  return beta_l[k] * beta_l[k] / (2 * M_PI * l * l) * std::sqrt(e * i / (rho * a));
}
} // namespace chipflex::fem::testing
