#pragma once
// The geometrically nonlinear (St Venant-Kirchhoff, total Lagrangian) terms of a reduced
// basis, integrated element by element with the FE quadrature of the body's stiffness
// matrix. With u = sum_a q_a psi_a and H_a = grad psi_a, the Green-Lagrange strain is
//     E = sum_a q_a L_a + 1/2 sum_ab q_a q_b B_ab,   L_a = sym H_a,
//     B_ab = 1/2 (H_a^T H_b + H_b^T H_a),
// and the strain energy density W = 1/2 <E, E> with <X, Y> = 2 mu X:Y + lambda trX trY.
// Expanding W gives the reduced internal force as an exact cubic polynomial (Barbic & James
// 2005; common/polynomial_stiffness.h):
//     K_ij   = int <L_i, L_j>                                   (= Psi^T K Psi)
//     Q_ijk  = 1/2 int (<L_i, B_jk> + <L_j, B_ik> + <L_k, B_ij>)
//     C_ijkl = 1/6 int (<B_ij, B_kl> + <B_ik, B_jl> + <B_il, B_jk>)
// Both are fully symmetric. The unique products <L_i, B_jk> and <B_ij, B_kl> are sums over
// quadrature points of small dense products (Mandel vectors of the strains, weighted by
// the Cholesky factor of the elasticity matrix), so the cost is ~ n_qp (m^2/2)^2.
//
// Static modal derivatives (Idelsohn & Cardona 1985, "A reduction method for nonlinear
// structural dynamic analysis", CMAME 49): d phi_i / d q_j = -K^-1 (dK_t/dq_j) phi_i, where
// (dK_t/dq_j) phi_i is the second derivative of the FE internal force in the directions
// phi_i, phi_j:
//     r_ij[node b, component c] = int [(S(B_ij) + H_j S(L_i) + H_i S(L_j)) grad N_b]_c,
// S(X) = 2 mu X + lambda tr(X) 1 (symmetric in i, j).
//
// Both functions work on node-ordered fields (row node*dim + component) and are collective
// over the body's communicator (each process integrates its own cells; the sums are shared).

#include "fem/elastic_body.h"

#include <utility>
#include <vector>

namespace chipflex::fem
{
struct SvkPolynomial
{
  Eigen::MatrixXd linear;        ///< K_ij from the same quadrature (a check on Psi^T K Psi)
  std::vector<double> quadratic; ///< Q, sorted i <= j <= k
  std::vector<double> cubic;     ///< C, sorted i <= j <= k <= l
};

template <int dim>
SvkPolynomial svk_polynomial(const ElasticBody<dim>& body, const Eigen::MatrixXd& basis);

/// r_ij for the given pairs of columns of `modes`, clamped DoFs zeroed (node-ordered).
template <int dim>
std::vector<Eigen::VectorXd> svk_second_order_forces(const ElasticBody<dim>& body,
                                                     const Eigen::MatrixXd& modes,
                                                     const std::vector<std::pair<int, int>>& pairs);
} // namespace chipflex::fem
