// NonlinearElasticBody: total-Lagrangian hyperelastic FE model, Newton statics and
// generalised-alpha dynamics (fem/nonlinear_elastic_body.h).

#include "fem/nonlinear_elastic_body.h"

#include "common/input_error.h"
#include "fem/direct_solver.h"
#include "fem/petsc_check.h"
#include "fem/petsc_matrix_setup.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <stdexcept>

namespace chipflex::fem
{
namespace
{
/// Generalised-alpha parameters for a spectral radius rho at infinite frequency (Chung &
/// Hulbert 1993, eqs. 25, 17, 20): second-order accurate, rho = 1 the trapezoidal rule.
struct GeneralisedAlpha
{
  explicit GeneralisedAlpha(double rho)
      : alpha_m((2 * rho - 1) / (rho + 1)), alpha_f(rho / (rho + 1)),
        gamma(0.5 - alpha_m + alpha_f),
        beta(0.25 * (1 - alpha_m + alpha_f) * (1 - alpha_m + alpha_f))
  {
  }
  double alpha_m, alpha_f, gamma, beta;
};
} // namespace

template <int dim>
NonlinearElasticBody<dim>::NonlinearElasticBody(const GmshMeshData& mesh, const Material& material,
                                                HyperelasticModel model, unsigned int degree,
                                                const std::string& clamp_group,
                                                MPI_Comm communicator, NewtonOptions newton)
    : model_(model), newton_(newton)
{
  if (dim == 2 && material.plane_stress && model == HyperelasticModel::neo_hooke)
    throw InputError("--material", "neo-Hooke exists in plane strain and 3D only (plane stress "
                                   "would need the thickness stretch solved at every point); "
                                   "use svk for plane stress");
  linear = std::make_unique<ElasticBody<dim>>(mesh, material, degree, clamp_group, communicator);
  linear->setup_system();
  linear->assemble_system();
  lambda_ = material.lame_lambda(dim);
  mu_ = material.shear_modulus();

  // The tangent has the linear stiffness's pattern (the same couplings of the same cells).
  const ElasticBody<dim>& b = *linear;
  const IndexSet relevant =
      DoFTools::locally_relevant_dofs_per_subdomain(b.dof_handler)[b.this_process];
  DynamicSparsityPattern dsp(relevant);
  DoFTools::make_sparsity_pattern(b.dof_handler, dsp, b.constraints, false, b.this_process);
  SparsityTools::distribute_sparsity_pattern(dsp, b.locally_owned_dofs, b.communicator, relevant);
  reinit_from_pattern(tangent_, dsp, b.locally_owned_dofs, b.communicator);
  for (auto* v : {&u_, &v_, &a_, &force_, &internal_force_})
    *v = b.new_vector();
}

template <int dim>
double NonlinearElasticBody<dim>::assemble(const DofVector& u, DofVector* internal_force,
                                           bool tangent)
{
  const ElasticBody<dim>& b = *linear;
  const auto& fe = *b.fe;
  const Quadrature<dim> quadrature = b.mesh.simplex
                                         ? Quadrature<dim>(QGaussSimplex<dim>(b.degree + 1))
                                         : Quadrature<dim>(QGauss<dim>(b.degree + 1));
  FEValues<dim> fe_values(*b.mapping, fe, quadrature, update_gradients | update_JxW_values);
  const unsigned int n_base = fe.base_element(0).n_dofs_per_cell();
  const unsigned int n = fe.n_dofs_per_cell();
  std::vector<unsigned int> system_index(n_base * dim);
  for (unsigned int a = 0; a < n_base; ++a)
    for (unsigned int c = 0; c < dim; ++c)
      system_index[a * dim + c] = fe.component_to_system_index(c, a);

  const Vector<double> all(u); // every process reads its cells' values
  std::vector<types::global_dof_index> local(n);
  std::vector<Tensor<1, dim>> grad(n_base);
  std::vector<double> u_local(n);                     // (a, i) ordering
  std::vector<SymmetricTensor<2, dim>> dE(n), CdE(n); // virtual strains, C : dE
  std::vector<Tensor<1, dim>> Sg(n_base);
  FullMatrix<double> k_local(n), k_system(n);
  Vector<double> f_local(n), f_system(n);
  if (internal_force)
    *internal_force = 0;
  if (tangent)
    tangent_ = 0;
  double energy = 0;

  for (const auto& cell : b.dof_handler.active_cell_iterators())
  {
    if (cell->subdomain_id() != b.this_process)
      continue;
    fe_values.reinit(cell);
    cell->get_dof_indices(local);
    for (unsigned int k = 0; k < n; ++k)
      u_local[k] = all[local[system_index[k]]];
    f_local = 0;
    k_local = 0;
    for (unsigned int q = 0; q < quadrature.size(); ++q)
    {
      const double jxw = fe_values.JxW(q);
      Tensor<2, dim> H; // grad u
      for (unsigned int a = 0; a < n_base; ++a)
      {
        grad[a] = fe_values.shape_grad(system_index[a * dim], q);
        for (unsigned int i = 0; i < dim; ++i)
          H[i] += u_local[a * dim + i] * grad[a];
      }
      const auto point = evaluate_hyperelastic<dim>(model_, lambda_, mu_, H, tangent);
      const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + H;
      energy += point.energy * jxw;
      const Tensor<2, dim> P = F * Tensor<2, dim>(point.stress); // first Piola-Kirchhoff
      for (unsigned int a = 0; a < n_base; ++a)
        for (unsigned int i = 0; i < dim; ++i)
          f_local(a * dim + i) += (P[i] * grad[a]) * jxw;
      if (!tangent)
        continue;
      // dE of the shape function N_a e_i: sym(F^T (e_i (x) Grad N_a)) = sym(F_i (x) Grad N_a).
      for (unsigned int a = 0; a < n_base; ++a)
      {
        Sg[a] = point.stress * grad[a];
        for (unsigned int i = 0; i < dim; ++i)
        {
          dE[a * dim + i] = symmetrize(outer_product(F[i], grad[a]));
          CdE[a * dim + i] = point.tangent * dE[a * dim + i];
        }
      }
      for (unsigned int a = 0; a < n_base; ++a)
        for (unsigned int b2 = 0; b2 < n_base; ++b2)
        {
          const double geometric = (grad[a] * Sg[b2]) * jxw;
          for (unsigned int i = 0; i < dim; ++i)
          {
            k_local(a * dim + i, b2 * dim + i) += geometric;
            for (unsigned int j = 0; j < dim; ++j)
              k_local(a * dim + i, b2 * dim + j) += (dE[a * dim + i] * CdE[b2 * dim + j]) * jxw;
          }
        }
    }
    if (internal_force)
    {
      for (unsigned int k = 0; k < n; ++k)
        f_system(system_index[k]) = f_local(k);
      b.constraints.distribute_local_to_global(f_system, local, *internal_force);
    }
    if (tangent)
    {
      for (unsigned int k = 0; k < n; ++k)
        for (unsigned int l = 0; l < n; ++l)
          k_system(system_index[k], system_index[l]) = k_local(k, l);
      b.constraints.distribute_local_to_global(k_system, local, tangent_);
    }
  }
  if (internal_force)
    internal_force->compress(VectorOperation::add);
  if (tangent)
    tangent_.compress(VectorOperation::add);
  return Utilities::MPI::sum(energy, b.communicator);
}

template <int dim>
typename NonlinearElasticBody<dim>::DofVector
NonlinearElasticBody<dim>::solve_static(const DofVector& force, unsigned int increments,
                                        StaticSolveStatistics* statistics)
{
  const ElasticBody<dim>& b = *linear;
  if (!b.is_clamped())
    throw InputError("--clamp", "the nonlinear static solve needs a clamped body");
  if (increments < 1)
    throw std::invalid_argument("solve_static: at least one load increment");
  StaticSolveStatistics local_statistics;
  StaticSolveStatistics& s = statistics ? *statistics : local_statistics;
  s = {};
  DofVector u = b.new_vector(), trial = b.new_vector(), f = b.new_vector(),
            residual = b.new_vector(), du = b.new_vector(), f_int = b.new_vector();
  u = 0;
  // Newton from `trial` for the load f; false if it does not converge.
  auto newton = [&]() -> bool
  {
    for (unsigned int it = 0; it <= newton_.max_iterations; ++it)
    {
      try
      {
        assemble(trial, &f_int, true);
      }
      catch (const std::runtime_error&) // an inverted element: cut the increment
      {
        return false;
      }
      residual = f;
      residual -= f_int;
      const double scale = std::max(f.l2_norm(), f_int.l2_norm());
      if (residual.l2_norm() <= newton_.tolerance * scale ||
          (it > 0 && du.l2_norm() <= newton_.increment_tolerance * trial.l2_norm()))
        return true;
      if (it == newton_.max_iterations || !std::isfinite(residual.l2_norm()))
        return false;
      const DirectSolver solver(1, tangent_, 0, b.mass_matrix, b.node_block_size);
      solver.solve(residual, du);
      trial += du;
      ++s.newton_iterations;
    }
    return false;
  };
  double done = 0, increment = 1.0 / increments;
  unsigned int cuts = 0;
  while (done < 1 - 1e-12)
  {
    const double size = std::min(increment, 1 - done);
    trial = u;
    f.equ(done + size, force);
    if (newton())
    {
      u = trial;
      done += size;
      ++s.increments;
    }
    else
    {
      if (++cuts > 8)
        throw std::runtime_error("nonlinear static solve: Newton fails at load factor " +
                                 std::to_string(done) + " even with increment " +
                                 std::to_string(size));
      increment = size / 2;
    }
  }
  return u;
}

template <int dim>
Eigen::VectorXd NonlinearElasticBody<dim>::solve_static(const LoadCase& load,
                                                        unsigned int increments,
                                                        StaticSolveStatistics* statistics)
{
  return linear->to_nodal(solve_static(linear->load_vector(load), increments, statistics));
}

template <int dim>
void NonlinearElasticBody<dim>::start_dynamics(const DynamicsOptions& options, const DofVector& u0,
                                               const DofVector& v0, const DofVector& force)
{
  if (!(options.rho_infinity >= 0 && options.rho_infinity <= 1))
    throw InputError("rho infinity", "must lie in [0, 1]");
  if (options.rayleigh_mass < 0 || options.rayleigh_stiffness < 0)
    throw InputError("rayleigh damping", "coefficients must not be negative");
  dynamics_ = options;
  const ElasticBody<dim>& b = *linear;
  u_ = u0;
  v_ = v0;
  force_ = force;
  assemble(u_, &internal_force_, false);
  // M a0 = f - f_int(u0) - C v0
  DofVector rhs = force_, scratch = b.new_vector();
  rhs -= internal_force_;
  if (options.rayleigh_mass > 0 || options.rayleigh_stiffness > 0)
  {
    b.mass_matrix.vmult(scratch, v_);
    rhs.add(-options.rayleigh_mass, scratch);
    b.stiffness_matrix.vmult(scratch, v_);
    rhs.add(-options.rayleigh_stiffness, scratch);
  }
  b.constraints.set_zero(rhs);
  DirectSolver(0, b.stiffness_matrix, 1, b.mass_matrix, b.node_block_size).solve(rhs, a_);
}

template <int dim>
void NonlinearElasticBody<dim>::set_state(const DynamicsOptions& options, const DofVector& u,
                                          const DofVector& v, const DofVector& a,
                                          const DofVector& force)
{
  dynamics_ = options;
  u_ = u;
  v_ = v;
  a_ = a;
  force_ = force;
  assemble(u_, &internal_force_, false);
}

template <int dim>
unsigned int NonlinearElasticBody<dim>::step(double dt, const DofVector& force)
{
  if (!(dt > 0))
    throw std::invalid_argument("NonlinearElasticBody::step: dt must be positive");
  return step_or_split(dt, force, 0);
}

// A step whose Newton iteration fails (a fast-turning slender part can send the first
// correction far off) is taken as two half steps, the load interpolated linearly between
// the step's ends; the state is the one of step n until a step succeeds.
template <int dim>
unsigned int NonlinearElasticBody<dim>::step_or_split(double dt, const DofVector& force,
                                                      unsigned int depth)
{
  const int iterations = try_step(dt, force);
  if (iterations >= 0)
    return iterations;
  if (depth >= 6)
    throw std::runtime_error("nonlinear dynamics: Newton does not converge in " +
                             std::to_string(newton_.max_iterations) +
                             " iterations, even with the step split 64 times (step " +
                             std::to_string(dt) + " s)");
  DofVector middle = force;
  middle.add(1.0, force_);
  middle *= 0.5;
  unsigned int total = step_or_split(dt / 2, middle, depth + 1);
  total += step_or_split(dt / 2, force, depth + 1);
  return total;
}

template <int dim>
int NonlinearElasticBody<dim>::try_step(double dt, const DofVector& force)
{
  const ElasticBody<dim>& b = *linear;
  const GeneralisedAlpha c(dynamics_.rho_infinity);
  const double alpha_r = dynamics_.rayleigh_mass, beta_r = dynamics_.rayleigh_stiffness;
  const bool damped = alpha_r > 0 || beta_r > 0;

  // Everything of step n in one vector: the weighted load minus the old state's share,
  //   g = (1 - af) f1 + af f0 - af (C v0 + f_int0) - am M a0,
  // so that the residual is R(u1) = g - (1 - am) M a1 - (1 - af) (C v1 + f_int(u1)).
  DofVector g = b.new_vector(), scratch = b.new_vector(), cv = b.new_vector();
  g.equ(1 - c.alpha_f, force);
  g.add(c.alpha_f, force_, -c.alpha_f, internal_force_);
  b.mass_matrix.vmult(scratch, a_);
  g.add(-c.alpha_m, scratch);
  if (damped)
  {
    b.mass_matrix.vmult(scratch, v_);
    b.stiffness_matrix.vmult(cv, v_);
    g.add(-c.alpha_f * alpha_r, scratch, -c.alpha_f * beta_r, cv);
  }
  // Newmark: a1 = (u1 - u0 - dt v0) / (beta dt^2) - (1 / (2 beta) - 1) a0,
  //          v1 = v0 + dt ((1 - gamma) a0 + gamma a1).
  DofVector u1 = u_, a1 = b.new_vector(), v1 = b.new_vector(), residual = b.new_vector(),
            du = b.new_vector(), f_int = b.new_vector();
  // Predictor: u1 = u0. Extrapolating (constant velocity or acceleration) moves the nodes
  // of a rotating slender part along straight lines, which stretches it: residuals 1e8 times
  // the load on a swinging 100:1 beam, and Newton wandering for 25 iterations.
  auto kinematics = [&]()
  {
    a1 = u1;
    a1 -= u_;
    a1.add(-dt, v_);
    a1 *= 1 / (c.beta * dt * dt);
    a1.add(-(1 / (2 * c.beta) - 1), a_);
    v1 = v_;
    v1.add(dt * (1 - c.gamma), a_, dt * c.gamma, a1);
  };
  const double c_m =
      (1 - c.alpha_m) / (c.beta * dt * dt) + (1 - c.alpha_f) * c.gamma / (c.beta * dt) * alpha_r;
  const double c_k0 = (1 - c.alpha_f) * c.gamma / (c.beta * dt) * beta_r;
  std::unique_ptr<DirectSolver> solver;
  for (unsigned int it = 0; it <= newton_.max_iterations; ++it)
  {
    kinematics();
    try
    {
      assemble(u1, &f_int, false);
    }
    catch (const std::runtime_error&) // an inverted element (neo-Hooke): split the step
    {
      return -1;
    }
    // R = g - (1 - am) M a1 - (1 - af) (C v1 + f_int)
    residual = g;
    b.mass_matrix.vmult(scratch, a1);
    const double inertia = (1 - c.alpha_m) * scratch.l2_norm();
    residual.add(-(1 - c.alpha_m), scratch, -(1 - c.alpha_f), f_int);
    if (damped)
    {
      b.mass_matrix.vmult(scratch, v1);
      b.stiffness_matrix.vmult(cv, v1);
      residual.add(-(1 - c.alpha_f) * alpha_r, scratch, -(1 - c.alpha_f) * beta_r, cv);
    }
    b.constraints.set_zero(residual);
    const double scale = std::max({force.l2_norm(), f_int.l2_norm(), inertia});
    if (residual.l2_norm() <= newton_.tolerance * scale ||
        (it > 0 && du.l2_norm() <= newton_.increment_tolerance * u1.l2_norm()))
    {
      u_ = u1;
      v_ = v1;
      a_ = a1;
      force_ = force;
      internal_force_ = f_int;
      return int(it);
    }
    if (!std::isfinite(residual.l2_norm()) || it == newton_.max_iterations)
      break;
    // The Jacobian -dR/du1 = (1 - af) K_T + c_k0 K0 + c_m M, refactorised every iteration
    // (full Newton: quadratic convergence, usually 2-3 iterations per step).
    try
    {
      assemble(u1, nullptr, true);
    }
    catch (const std::runtime_error&)
    {
      return -1;
    }
    CHIPFLEX_PETSC_CHECK(MatScale(tangent_.petsc_matrix(), 1 - c.alpha_f));
    if (c_k0 != 0)
    {
      const Mat k0 = b.stiffness_matrix;
      CHIPFLEX_PETSC_CHECK(MatAXPY(tangent_.petsc_matrix(), c_k0, k0, SUBSET_NONZERO_PATTERN));
    }
    solver = std::make_unique<DirectSolver>(1, tangent_, c_m, b.mass_matrix, b.node_block_size);
    solver->solve(residual, du);
    u1 += du;
  }
  return -1;
}

template <int dim>
double NonlinearElasticBody<dim>::kinetic_energy() const
{
  DofVector mv = linear->new_vector();
  linear->mass_matrix.vmult(mv, v_);
  return 0.5 * (mv * v_);
}

template class NonlinearElasticBody<2>;
template class NonlinearElasticBody<3>;
} // namespace chipflex::fem
