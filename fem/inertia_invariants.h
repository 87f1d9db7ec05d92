#pragma once
// The inertia quantities of the floating-frame equations, from the consistent scalar mass
// matrix Ms (not a lumped approximation). With node-wise fields a, b (n x dim matrices)
//     C(a, b) = sum_ij Ms_ij a_i b_j^T = a^T Ms b          (dim x dim)
// every term follows (docs/body_file_format.md): mass = 1^T Ms 1, centre of mass
// C(x, 1)/mass, Phi_t^T M Psi, x~^T M Psi, Psi~^T M Psi~ and the reduced mass matrix
// M_red(k, l) = trace C(psi_k, psi_l).

#include "common/reduced_body_file.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace chipflex::fem
{
/// Fills mass, center_of_mass, inertia_tensor, c_xx, translation_coupling, c_x_psi,
/// c_psi_psi and mass_matrix of `body` from body.nodes, body.psi and Ms.
/// In 2D the inertia tensor is per metre of depth with z out of plane.
void compute_inertia_invariants(const Eigen::SparseMatrix<double>& scalar_mass,
                                ReducedBodyData& body);
} // namespace chipflex::fem
