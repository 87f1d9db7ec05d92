#pragma once
// The hyperelastic laws of the nonlinear FE model by name (fem/hyperelastic_material.h has
// the laws themselves); no deal.II here, so that case-file and command-line code can name them.

#include "common/input_error.h"

#include <string>

namespace chipflex::fem
{
enum class HyperelasticModel
{
  st_venant_kirchhoff,
  neo_hooke
};

/// "svk" / "st-venant-kirchhoff" or "neo-hooke"; InputError at `where` otherwise.
inline HyperelasticModel parse_hyperelastic_model(const std::string& text, const std::string& where)
{
  if (text == "svk" || text == "st-venant-kirchhoff" || text == "saint-venant-kirchhoff")
    return HyperelasticModel::st_venant_kirchhoff;
  if (text == "neo-hooke" || text == "neohooke")
    return HyperelasticModel::neo_hooke;
  throw InputError(where, "unknown material model '" + text + "' (expected svk or neo-hooke)");
}

inline std::string hyperelastic_model_name(HyperelasticModel model)
{
  return model == HyperelasticModel::st_venant_kirchhoff ? "svk" : "neo-hooke";
}

} // namespace chipflex::fem
