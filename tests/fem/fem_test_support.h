#pragma once
// Shared by the fem tests: meshes in a scratch folder and a one-call reduction.

#include "fem/reduce.h"
#include "meshes/block_mesher.h"

#include <cmath>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace chipflex::fem::testing
{
inline std::string scratch(const std::string& name)
{
  static const std::string folder = []
  {
    std::string d = "fem_test_scratch_" + std::to_string(::getpid());
    std::system(("mkdir -p " + d).c_str());
    return d;
  }();
  return folder + "/" + name;
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
