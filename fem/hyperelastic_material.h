#pragma once
// Hyperelastic laws of the geometrically nonlinear FE model (fem/nonlinear_elastic_body.h):
// the strain energy density W, the second Piola-Kirchhoff stress S = dW/dE and the material
// tangent C = d^2W/dE^2 at one point, from the deformation gradient F (total Lagrangian).
// deal.II tensors; include only from fem/.
//
//   St Venant-Kirchhoff:   W = lambda/2 (tr E)^2 + mu E:E,   S = lambda tr(E) I + 2 mu E
//   compressible neo-Hooke (Bonet & Wood, Nonlinear Continuum Mechanics for FE Analysis,
//   2nd ed. 2008, eqs. 6.28, 6.29, 6.40):
//                          W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,
//                          S = mu (I - C^-1) + lambda ln(J) C^-1,
//                          C = lambda C^-1 (x) C^-1 + 2 (mu - lambda ln J) I_{C^-1}
// with E = (F^T F - I)/2, C = F^T F, J = det F, I1 = tr C. Both reduce to Hooke's law with
// the Lame constants lambda, mu at small strain. In 2D the model is plane strain (F33 = 1,
// so I1 = tr C + 1 and J = det F of the in-plane block); plane stress exists for St
// Venant-Kirchhoff, where S33 = 0 is exact with lambda -> 2 lambda mu / (lambda + 2 mu)
// (Material::lame_lambda), and is refused for neo-Hooke, which would need a local solve
// for the thickness stretch.

#include "fem/hyperelastic_model.h"

#include <cmath>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <string>

namespace chipflex::fem
{
template <int dim>
struct HyperelasticPoint
{
  double energy = 0;                       ///< W, J/m^3
  dealii::SymmetricTensor<2, dim> stress;  ///< S, Pa
  dealii::SymmetricTensor<4, dim> tangent; ///< dS/dE, Pa
};

/// The law at deformation gradient F. `compute_tangent` false skips C (residual only).
/// Throws std::runtime_error for J <= 0 under neo-Hooke (an inverted element: Newton
/// overshoot, handled by the caller's load-step cut).
template <int dim>
HyperelasticPoint<dim> evaluate_hyperelastic(HyperelasticModel model, double lambda, double mu,
                                             const dealii::Tensor<2, dim>& F, bool compute_tangent)
{
  using namespace dealii;
  HyperelasticPoint<dim> p;
  const SymmetricTensor<2, dim> C = symmetrize(transpose(F) * F);
  const SymmetricTensor<2, dim> I = unit_symmetric_tensor<dim>();
  if (model == HyperelasticModel::st_venant_kirchhoff)
  {
    const SymmetricTensor<2, dim> E = 0.5 * (C - I);
    const double trace_e = trace(E);
    p.energy = 0.5 * lambda * trace_e * trace_e + mu * (E * E);
    p.stress = lambda * trace_e * I + 2 * mu * E;
    if (compute_tangent)
      p.tangent = lambda * outer_product(I, I) + 2 * mu * identity_tensor<dim>();
    return p;
  }
  const double J = determinant(F);
  if (!(J > 0))
    throw std::runtime_error("neo-Hooke: inverted element (det F = " + std::to_string(J) + ")");
  const double log_j = std::log(J);
  const SymmetricTensor<2, dim> C_inv = invert(C);
  const double i1 = trace(C) + (3 - dim); // plane strain: C33 = 1
  p.energy = 0.5 * mu * (i1 - 3) - mu * log_j + 0.5 * lambda * log_j * log_j;
  p.stress = mu * (I - C_inv) + lambda * log_j * C_inv;
  if (compute_tangent)
  {
    // I_{C^-1}_{IJKL} = (Cinv_IK Cinv_JL + Cinv_IL Cinv_JK) / 2
    SymmetricTensor<4, dim> i_c_inv;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = a; b < dim; ++b)
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int d = c; d < dim; ++d)
            i_c_inv[a][b][c][d] = 0.5 * (C_inv[a][c] * C_inv[b][d] + C_inv[a][d] * C_inv[b][c]);
    p.tangent = lambda * outer_product(C_inv, C_inv) + 2 * (mu - lambda * log_j) * i_c_inv;
  }
  return p;
}
} // namespace chipflex::fem
