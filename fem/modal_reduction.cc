#include "fem/modal_reduction.h"

#include "common/input_error.h"
#include "common/wall_clock.h"
#include "fem/direct_solver.h"
#include "fem/eigen_solver.h"
#include "fem/svk_reduced_forces.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace chipflex::fem
{
namespace
{

/// sum_i A_ii / sum_i B_ii: a typical eigenvalue, used to scale shifts.
double diagonal_ratio(const PETScWrappers::MPI::SparseMatrix& a,
                      const PETScWrappers::MPI::SparseMatrix& b,
                      const PETScWrappers::MPI::Vector& layout)
{
  auto da = layout, db = layout;
  MatGetDiagonal(a, da);
  MatGetDiagonal(b, db);
  PetscScalar sa, sb;
  VecSum(da, &sa);
  VecSum(db, &sb);
  return PetscRealPart(sa) / PetscRealPart(sb);
}

/// The sign convention: the first (lowest row) entry within 1e-6 of the largest magnitude
/// is positive; the tolerance keeps mirror-symmetric ties from flipping with round-off.
bool has_negative_sign(const Eigen::VectorXd& v)
{
  const double largest = v.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (std::abs(v[i]) >= (1 - 1e-6) * largest)
      return v[i] < 0;
  return false;
}
} // namespace

template <int dim>
ModalReduction<dim>::ModalReduction(const ElasticBody<dim>& body_, unsigned int n_modes_,
                                    std::vector<LoadCase> static_cases_,
                                    unsigned int n_derivative_modes_)
    : body(body_), n_modes(n_modes_), static_cases(std::move(static_cases_)),
      n_derivative_modes(n_derivative_modes_)
{
  if (n_modes == 0 && static_cases.empty())
    throw InputError("--modes", "must be at least 1 (or give --static-modes)");
  if (n_derivative_modes > n_modes)
    throw InputError("--modal-derivatives", "uses the first N normal modes: at most --modes (" +
                                                std::to_string(n_modes) + ")");
}

template <int dim>
ModalReduction<dim>::~ModalReduction() = default;

template <int dim>
Eigen::VectorXd ModalReduction<dim>::apply_mass(const Eigen::VectorXd& v) const
{
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const int n = body.n_nodes();
  RowMajor result = body.scalar_mass_matrix * Eigen::Map<const RowMajor>(v.data(), n, dim);
  return Eigen::Map<Eigen::VectorXd>(result.data(), v.size());
}

template <int dim>
void ModalReduction<dim>::run(ReductionTimings& timings)
{
  if (!body.is_clamped())
    compute_rigid_modes();
  compute_normal_modes(timings);
  const auto t0 = std::chrono::steady_clock::now();
  compute_static_modes(timings);
  compute_modal_derivatives();
  timings.static_modes = seconds_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  orthonormalise_and_fix_signs();
  compute_reduced_stiffness();
  rotate_static_modes_to_ritz_vectors();
  timings.basis = seconds_since(t1);
}

// Translations and rotations about the centre of mass, M-orthonormalised.
template <int dim>
void ModalReduction<dim>::compute_rigid_modes()
{
  const int n = body.n_nodes(), n_rigid = dim * (dim + 1) / 2;
  Eigen::VectorXd centre = Eigen::VectorXd::Zero(dim),
                  masses = body.scalar_mass_matrix * Eigen::VectorXd::Ones(n);
  for (int i = 0; i < n; ++i)
    for (int d = 0; d < dim; ++d)
      centre[d] += masses[i] * body.node_coordinates[i][d] / masses.sum();
  rigid = Eigen::MatrixXd::Zero(dim * n, n_rigid);
  for (int i = 0; i < n; ++i)
  {
    double r[3] = {0, 0, 0};
    for (int d = 0; d < dim; ++d)
      r[d] = body.node_coordinates[i][d] - centre[d];
    for (int d = 0; d < dim; ++d)
      rigid(i * dim + d, d) = 1;
    if (dim == 2)
    {
      rigid(i * dim + 0, 2) = -r[1];
      rigid(i * dim + 1, 2) = r[0];
    }
    else // e_a x r for a = x, y, z
      for (int a = 0; a < 3; ++a)
      {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        rigid(i * dim + c, dim + a) = r[b];
        rigid(i * dim + b, dim + a) = -r[c];
      }
  }
  for (int k = 0; k < n_rigid; ++k)
    for (int pass = 0; pass < 2; ++pass)
    {
      for (int l = 0; l < k; ++l)
        rigid.col(k) -= rigid.col(l) * rigid.col(l).dot(apply_mass(rigid.col(k)));
      rigid.col(k) /= std::sqrt(rigid.col(k).dot(apply_mass(rigid.col(k))));
    }
}

template <int dim>
void ModalReduction<dim>::compute_normal_modes(ReductionTimings& timings)
{
  normal.clear();
  eigenvalues.clear();
  if (n_modes == 0)
    return;
  const auto layout = body.new_vector();
  const unsigned int n_rigid = rigid.cols();
  // Clamped: K is positive definite, shift 0. Free-free: K is singular; a shift of
  // -1e-8 times a typical eigenvalue keeps K - sigma M regular (condition ~1e8) while the
  // rigid modes (lambda = 0) stay the nearest and are found and discarded.
  double target =
      n_rigid ? -1e-8 * diagonal_ratio(body.stiffness_matrix, body.mass_matrix, layout) : 0.;
  const unsigned int n_wanted = n_modes + n_rigid;
  const auto n_free = body.dof_handler.n_dofs() -
                      (body.is_clamped() ? dim * body.node_sets.at(body.clamp_group).size() : 0);
  if (n_wanted >= n_free)
    throw InputError("--modes", "asks for " + std::to_string(n_modes) +
                                    " modes; the mesh has only " + std::to_string(n_free) +
                                    " free DoFs");
  // A free body's rigid modes are told from the elastic ones by the gap to the first elastic
  // eigenvalue, and the second shift below needs a clearly elastic one: with only one or
  // two elastic modes asked for, a slender chip's rigid eigenvalues are not resolved
  // against them. Solve for at least as many elastic modes as rigid ones and keep those
  // asked for.
  const unsigned int n_solved =
      n_rigid ? std::min<unsigned int>(n_rigid + std::max(n_modes, n_rigid), n_free - 1) : n_wanted;
  auto solution = solve_eigenproblem(body.stiffness_matrix, body.mass_matrix, n_solved, target,
                                     layout, body.node_block_size);
  timings.factorisation = solution.factorisation_seconds;
  timings.eigen_solve = solution.solve_seconds;
  if (n_rigid)
  {
    // A slender, flexible body (a long curled chip) can have its first elastic eigenvalue
    // far below that shift. The inverted eigenvalues 1 / (lambda - sigma) of the rigid
    // and the low elastic modes then nearly coincide and Krylov-Schur may return the
    // wrong ones (four of six rigid modes for a two-turn helical chip). Solve again with
    // the shift a hundredth of the lowest clearly elastic eigenvalue found.
    double lowest_elastic = 0;
    for (const double lambda : solution.eigenvalues)
      if (lambda > 1e-4 * solution.eigenvalues.back())
      {
        lowest_elastic = lambda;
        break;
      }
    if (lowest_elastic > 0 && -target > lowest_elastic)
    {
      target = -1e-2 * lowest_elastic;
      solution = solve_eigenproblem(body.stiffness_matrix, body.mass_matrix, n_solved, target,
                                    layout, body.node_block_size);
      timings.factorisation += solution.factorisation_seconds;
      timings.eigen_solve += solution.solve_seconds;
    }
  }

  if (n_rigid)
  {
    const double first_elastic = solution.eigenvalues[n_rigid];
    for (unsigned int k = 0; k < n_rigid; ++k)
      if (std::abs(solution.eigenvalues[k]) > 1e-4 * first_elastic)
        throw InputError(body.mesh.path, "the free body does not have exactly " +
                                             std::to_string(n_rigid) +
                                             " rigid-body modes (is it one connected piece?)");
    if (solution.eigenvalues[n_rigid - 1] < -1e-4 * first_elastic)
      throw std::logic_error("negative eigenvalue of an elastic body");
  }
  for (unsigned int k = n_rigid; k < n_wanted; ++k)
  {
    Eigen::VectorXd phi = body.to_nodal(solution.vectors[k]);
    if (n_rigid) // exact M-orthogonality to rigid motion
      phi -= rigid * (rigid.transpose() * apply_mass(phi));
    normal.push_back(phi);
    eigenvalues.push_back(solution.eigenvalues[k]);
  }
}

template <int dim>
Eigen::VectorXd ModalReduction<dim>::solve_static(Eigen::VectorXd f)
{
  const auto layout = body.new_vector();
  if (!static_solver)
  {
    // Free-free: solve (K + alpha M) u_{k+1} = f' + alpha M u_k, u made M-orthogonal to the
    // rigid modes each time; the elastic error shrinks by alpha/(lambda_1 + alpha) per step.
    static_shift = 0;
    if (rigid.cols())
      static_shift =
          std::max(eigenvalues.empty() ? 0. : 1e-3 * eigenvalues.front(),
                   1e-10 * diagonal_ratio(body.stiffness_matrix, body.mass_matrix, layout));
    static_solver = std::make_unique<DirectSolver>(1, body.stiffness_matrix, static_shift,
                                                   body.mass_matrix, body.node_block_size);
  }
  const double alpha = static_shift;
  auto rhs = layout, u_vec = layout;
  if (!rigid.cols())
  {
    body.from_nodal(f, rhs);
    static_solver->solve(rhs, u_vec);
    return body.to_nodal(u_vec);
  }
  f -= apply_mass(rigid * (rigid.transpose() * f)); // self-equilibrated (inertia relief)
  Eigen::VectorXd u = Eigen::VectorXd::Zero(f.size());
  for (int iteration = 0; iteration < 50; ++iteration)
  {
    body.from_nodal(f + alpha * apply_mass(u), rhs);
    static_solver->solve(rhs, u_vec);
    Eigen::VectorXd next = body.to_nodal(u_vec);
    next -= rigid * (rigid.transpose() * apply_mass(next));
    const double change = (next - u).norm();
    u = next;
    if (change <= 1e-13 * u.norm())
      break;
  }
  return u;
}

template <int dim>
void ModalReduction<dim>::compute_static_modes(ReductionTimings&)
{
  statics.clear();
  for (const auto& load : static_cases)
  {
    Eigen::VectorXd f = body.to_nodal(body.load_vector(load));
    if (f.norm() == 0)
      throw InputError("--static-modes " + load.text, "the load vanishes");
    statics.push_back(solve_static(f));
  }
}

// d phi_i / d q_j = -K^-1 r_ij (fem/svk_reduced_forces.h); the sign is irrelevant (the
// columns are normalised and sign-fixed later).
template <int dim>
void ModalReduction<dim>::compute_modal_derivatives()
{
  derivatives.clear();
  derivative_kinds.clear();
  if (n_derivative_modes == 0)
    return;
  Eigen::MatrixXd modes(body.dof_of_node.size(), n_derivative_modes);
  for (unsigned int i = 0; i < n_derivative_modes; ++i)
    modes.col(i) = normal[i];
  std::vector<std::pair<int, int>> pairs;
  for (unsigned int i = 0; i < n_derivative_modes; ++i)
    for (unsigned int j = i; j < n_derivative_modes; ++j)
      pairs.emplace_back(i, j);
  const auto forces = svk_second_order_forces(body, modes, pairs);
  for (std::size_t p = 0; p < pairs.size(); ++p)
  {
    derivatives.push_back(solve_static(-forces[p]));
    derivative_kinds.push_back("derivative:" + std::to_string(pairs[p].first + 1) + "," +
                               std::to_string(pairs[p].second + 1));
  }
}

template <int dim>
void ModalReduction<dim>::orthonormalise_and_fix_signs()
{
  // Modified Gram-Schmidt in the M inner product, twice ("twice is enough"). Keeping M c
  // for every accepted column c makes each projection a dot product, and M v follows the
  // projections (M (v - a c) = M v - a M c): one mass product per column in all (one per
  // projection, m^2 of them, cost 45 s at 350k DoFs).
  std::vector<Eigen::VectorXd> columns, mass_columns;
  kinds.clear();
  auto add = [&](Eigen::VectorXd v, const std::string& kind, bool may_drop = false)
  {
    Eigen::VectorXd mv = apply_mass(v);
    const double original = std::sqrt(v.dot(mv));
    for (int pass = 0; pass < 2; ++pass)
      for (std::size_t j = 0; j < columns.size(); ++j)
      {
        const double a = mass_columns[j].dot(v);
        v -= a * columns[j];
        mv -= a * mass_columns[j];
      }
    const double norm = std::sqrt(v.dot(mv));
    if (may_drop) // deflation: a modal derivative (nearly) in the span already
    {
      if (!(norm > 1e-3 * original))
        return;
    }
    else if (!(norm > 1e-8 * original))
      throw InputError("--static-modes " + kind.substr(7),
                       "adds nothing to the modes before it (linearly dependent)");
    v /= norm;
    mv /= norm;
    if (has_negative_sign(v))
    {
      v = -v;
      mv = -mv;
    }
    columns.push_back(std::move(v));
    mass_columns.push_back(std::move(mv));
    kinds.push_back(kind);
  };
  for (const auto& phi : normal)
    add(phi, "normal");
  for (std::size_t s = 0; s < statics.size(); ++s)
    add(statics[s], "static:" + static_cases[s].text);
  const std::size_t before = columns.size();
  for (std::size_t d = 0; d < derivatives.size(); ++d)
    add(derivatives[d], derivative_kinds[d], true);
  n_derivatives = static_cast<int>(columns.size() - before);
  basis.resize(body.dof_of_node.size(), columns.size());
  for (std::size_t k = 0; k < columns.size(); ++k)
    basis.col(k) = columns[k];
}

template <int dim>
void ModalReduction<dim>::compute_reduced_stiffness()
{
  const int m = basis.cols();
  Eigen::MatrixXd k_basis(basis.rows(), m);
  auto v = body.new_vector(), kv = body.new_vector();
  for (int k = 0; k < m; ++k)
  {
    body.from_nodal(basis.col(k), v);
    body.stiffness_matrix.vmult(kv, v);
    k_basis.col(k) = body.to_nodal(kv);
  }
  reduced_stiffness = basis.transpose() * k_basis;
  reduced_stiffness = 0.5 * (reduced_stiffness + reduced_stiffness.transpose()).eval();
}

// After Gram-Schmidt, K_red is diagonal on the normal block and the normal-static block is
// zero (Phi^T K s = Lambda Phi^T M s = 0, to the eigen solver's residual: measured 1e-14 of
// the largest entry), but the block of two or more static modes is full: their diagonal
// entries are Rayleigh quotients, not frequencies of the reduced model, and modal damping
// built on that diagonal would not be diagonal in its modes. Solving the small eigenproblem
// K_ss y = w^2 y of that block (M_ss = I, the basis being M-orthonormal) and rotating the
// static columns S <- S Y makes K_red diagonal while M_red stays the identity: each static
// column is then a Ritz vector of the span of the static modes, its diagonal entry a Ritz
// value w^2 of the whole reduced pair, ascending. The span is unchanged, and so is every
// undamped or Rayleigh-damped response of the reduced model (Y is orthogonal); only its
// coordinates differ.
template <int dim>
void ModalReduction<dim>::rotate_static_modes_to_ritz_vectors()
{
  // the static and the modal-derivative columns together
  const int n_static = statics.size() + n_derivatives, n_normal = normal.size();
  if (n_static < 2) // one static mode: its Rayleigh quotient is its Ritz value
    return;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ritz(
      reduced_stiffness.bottomRightCorner(n_static, n_static));
  if (ritz.info() != Eigen::Success)
    throw std::runtime_error("static-mode block of K_red: eigen decomposition failed");
  const Eigen::MatrixXd rotated = basis.rightCols(n_static) * ritz.eigenvectors();
  for (int k = 0; k < n_static; ++k)
  {
    const Eigen::VectorXd column = rotated.col(k);
    basis.col(n_normal + k) = has_negative_sign(column) ? Eigen::VectorXd(-column) : column;
  }
  compute_reduced_stiffness(); // Psi^T K Psi of the rotated basis, not a rotated copy of it
}

template class ModalReduction<2>;
template class ModalReduction<3>;
} // namespace chipflex::fem
