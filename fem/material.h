#pragma once
// Isotropic linear elastic material and the 2D model; SI units.

#include "common/input_error.h"

#include <string>

namespace chipflex::fem
{
struct Material
{
  double youngs_modulus = 1.2e7; ///< Pa (Antoci 2007 rubber gate)
  double poisson_ratio = 0.4;    ///< -
  double density = 1100;         ///< kg/m^3
  /// 2D only: plane stress (thin plate) instead of plane strain (long prism). Both are per
  /// metre of depth: mass, forces and inertia in 2D are per metre.
  bool plane_stress = false;

  /// Throws InputError for E <= 0, rho <= 0 or nu outside (-1, 0.5).
  void check() const
  {
    if (!(youngs_modulus > 0))
      throw InputError("--E",
                       "Young's modulus must be positive, got " + std::to_string(youngs_modulus));
    if (!(density > 0))
      throw InputError("--rho", "density must be positive, got " + std::to_string(density));
    if (!(poisson_ratio > -1 && poisson_ratio < 0.5))
      throw InputError("--nu", "Poisson's ratio must lie in (-1, 0.5), got " +
                                   std::to_string(poisson_ratio));
  }

  double shear_modulus() const { return youngs_modulus / (2 * (1 + poisson_ratio)); }

  /// First Lame parameter of the model: plane stress replaces lambda by
  /// 2 lambda mu / (lambda + 2 mu) (sigma_zz = 0 instead of eps_zz = 0).
  double lame_lambda(int dim) const
  {
    const double nu = poisson_ratio, e = youngs_modulus;
    const double lambda = e * nu / ((1 + nu) * (1 - 2 * nu));
    const double mu = shear_modulus();
    return (dim == 2 && plane_stress) ? 2 * lambda * mu / (lambda + 2 * mu) : lambda;
  }

  std::string model_name(int dim) const
  {
    return dim == 3 ? "solid_3d" : plane_stress ? "plane_stress" : "plane_strain";
  }
};
} // namespace chipflex::fem
