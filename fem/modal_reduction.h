#pragma once
// From an assembled ElasticBody to a mass-orthonormal reduced basis:
//   1. normal modes: K phi = omega^2 M phi (SLEPc). A free-free body's dim(dim+1)/2 rigid
//      modes are computed too (a small negative shift keeps K - sigma M regular), checked to
//      be ~0 and dropped; the elastic ones are made exactly M-orthogonal to the analytic
//      rigid modes. Rigid motion belongs to the floating frame.
//   2. static correction modes: K u = f for each load case; free-free bodies use inertia
//      relief (f projected onto self-equilibrated loads, u made M-orthogonal to rigid
//      motion), which is how a floating body responds quasi-statically.
//   3. the basis [Phi S] made M-orthonormal (static columns Gram-Schmidt against the
//      normal ones, twice). K_red is then diagonal on the normal block (Phi^T K s =
//      Lambda Phi^T M s = 0) and dense only on the small static block.
//   4. with two or more static modes, the static columns rotated to the Ritz vectors of
//      their block (K_ss y = w^2 y): K_red is diagonal, its diagonal the reduced model's
//      frequencies squared, M_red still the identity.
//   4'. with modal derivatives (nonlinear bodies, fem/svk_reduced_forces.h): the static
//      derivatives d phi_i / d q_j of the first N normal modes, all pairs i <= j, are added
//      after the static modes, Gram-Schmidt against everything before them; a derivative
//      that adds less than 1e-3 of its own norm is dropped (deflation), and the Ritz
//      rotation of step 4 covers the static and derivative columns together.
//   5. sign convention: in each column the first row (node*dim + component) whose magnitude
//      is within 1e-6 of the largest is positive, so every run, serial or `mpirun -np N`,
//      writes the same modes.

#include "fem/direct_solver.h"
#include "fem/elastic_body.h"
#include "fem/reduce.h"

#include <memory>

namespace chipflex::fem
{
template <int dim>
class ModalReduction
{
public:
  /// @param n_derivative_modes modal derivatives of the first N normal modes (0: none)
  ModalReduction(const ElasticBody<dim>& body, unsigned int n_modes,
                 std::vector<LoadCase> static_cases, unsigned int n_derivative_modes = 0);
  ~ModalReduction();

  void run(ReductionTimings& timings);

  Eigen::MatrixXd basis;             ///< (dim n) x m, node-ordered, M-orthonormal
  std::vector<std::string> kinds;    ///< "normal" / "static:<case>"
  Eigen::MatrixXd reduced_stiffness; ///< basis^T K basis, diagonal
  std::vector<double> eigenvalues;   ///< of the normal modes, omega^2
  int n_derivatives = 0;             ///< derivative columns kept (after deflation)

private:
  void compute_rigid_modes();
  void compute_normal_modes(ReductionTimings& timings);
  void compute_static_modes(ReductionTimings& timings);
  void compute_modal_derivatives();
  /// K u = f (free-free: inertia relief, u M-orthogonal to rigid motion), f node-ordered.
  Eigen::VectorXd solve_static(Eigen::VectorXd f);
  void orthonormalise_and_fix_signs();
  void compute_reduced_stiffness();
  void rotate_static_modes_to_ritz_vectors();

  Eigen::VectorXd apply_mass(const Eigen::VectorXd& v) const; ///< (Ms (x) I) v, nodal

  const ElasticBody<dim>& body;
  const unsigned int n_modes;
  const std::vector<LoadCase> static_cases;
  const unsigned int n_derivative_modes;
  std::unique_ptr<DirectSolver> static_solver;
  double static_shift = 0;
  Eigen::MatrixXd rigid; ///< M-orthonormal rigid-body modes (free-free only)
  std::vector<Eigen::VectorXd> normal, statics, derivatives;
  std::vector<std::string> derivative_kinds;
};
} // namespace chipflex::fem
