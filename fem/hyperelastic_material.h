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

/// The law at the displacement gradient H = grad u (F = I + H). `compute_tangent` false
/// skips C (residual only). Throws std::runtime_error for J <= 0 under neo-Hooke (an
/// inverted element: Newton overshoot, handled by the caller's load-step cut).
///
/// Everything is formed from H, never as a difference from I: E = (H + H^T + H^T H)/2
/// rather than (F^T F - I)/2, J - 1 from H's invariants, I - C^-1 = 2 C^-1 E. At a
/// displacement gradient of 1e-16 (a weightless body under its first, tiny fluid load)
/// I + H rounds away what H holds, the internal force becomes rounding noise hundreds of
/// times the load, and Newton cannot reach its relative tolerance.
template <int dim>
HyperelasticPoint<dim> evaluate_hyperelastic(HyperelasticModel model, double lambda, double mu,
                                             const dealii::Tensor<2, dim>& H, bool compute_tangent)
{
  using namespace dealii;
  HyperelasticPoint<dim> p;
  const SymmetricTensor<2, dim> I = unit_symmetric_tensor<dim>();
  const SymmetricTensor<2, dim> E = symmetrize(H) + 0.5 * symmetrize(transpose(H) * H);
  if (model == HyperelasticModel::st_venant_kirchhoff)
  {
    const double trace_e = trace(E);
    p.energy = 0.5 * lambda * trace_e * trace_e + mu * (E * E);
    p.stress = lambda * trace_e * I + 2 * mu * E;
    if (compute_tangent)
      p.tangent = lambda * outer_product(I, I) + 2 * mu * identity_tensor<dim>();
    return p;
  }
  // J - 1 = det(I + H) - 1 = tr H + I2(H) (+ det H in 3D), I2 = ((tr H)^2 - tr(H H)) / 2;
  // in 2D I2 = det H and there is no third term.
  const double tr_h = trace(H);
  const double i2 = 0.5 * (tr_h * tr_h - trace(H * H));
  const double j_minus_1 = tr_h + i2 + (dim == 3 ? determinant(H) : 0.0);
  if (!(j_minus_1 > -1))
    throw std::runtime_error(
        "neo-Hooke: inverted element (det F = " + std::to_string(1 + j_minus_1) + ")");
  const double log_j = std::log1p(j_minus_1);
  const SymmetricTensor<2, dim> C_inv = invert(SymmetricTensor<2, dim>(I + 2 * E));
  // I1 - 3 = tr C - dim = 2 tr E (plane strain: C33 = 1)
  p.energy = mu * trace(E) - mu * log_j + 0.5 * lambda * log_j * log_j;
  p.stress =
      2 * mu * symmetrize(Tensor<2, dim>(C_inv) * Tensor<2, dim>(E)) + lambda * log_j * C_inv;
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
