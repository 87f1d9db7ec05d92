#pragma once
// Isotropic linear elastic material and the 2D model; SI units.

#include "common/input_error.h"

#include <cmath>
#include <limits>
#include <string>

namespace chipflex::fem
{
/// No defaults for E, nu and rho: a generic body has no typical material, and a default
/// would silently give every body that forgot one the elastic gate's rubber. NaN marks
/// "not given"; check() names what is missing.
struct Material
{
  double youngs_modulus = std::numeric_limits<double>::quiet_NaN(); ///< Pa
  double poisson_ratio = std::numeric_limits<double>::quiet_NaN();  ///< -
  double density = std::numeric_limits<double>::quiet_NaN();        ///< kg/m^3
  /// 2D only: plane stress (thin plate) instead of plane strain (long prism). Both are per
  /// metre of depth: mass, forces and inertia in 2D are per metre.
  bool plane_stress = false;

  /// Throws InputError for a value not given, E <= 0, rho <= 0 or nu outside (-1, 0.5).
  /// The names are those of `chipflex reduce`, the one place a user sets them directly.
  void check() const
  {
    const std::string no_default = " (no default: every body states its material)";
    if (std::isnan(youngs_modulus))
      throw InputError("--E", "required: Young's modulus, Pa" + no_default);
    if (std::isnan(poisson_ratio))
      throw InputError("--nu", "required: Poisson's ratio, -" + no_default);
    if (std::isnan(density))
      throw InputError("--rho", "required: density, kg/m^3" + no_default);
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
