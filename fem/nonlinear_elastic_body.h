#pragma once
// The geometrically nonlinear finite-element model of one elastic body (deal.II; include
// only from fem/ and apps/; the deal.II-free face of it is fem/fe_body_model.h).
//
// Total Lagrangian: the unknowns are the nodal displacements u of the reference (mesh)
// configuration, the strain is Green-Lagrange's E = (F^T F - I)/2 with F = I + Grad u, and
// the internal virtual work is the integral of S : dE over the reference body, S from a
// hyperelastic law (fem/hyperelastic_material.h: St Venant-Kirchhoff or compressible
// neo-Hooke). Everything else is the linear model's (fem/elastic_body.h): the same mesh,
// element degree, curved isoparametric mapping of second-order meshes, node numbering,
// named node sets, skin, clamp constraints and consistent mass; a load case gives the
// same consistent nodal forces, applied as dead loads (fixed in size and direction).
//
// Statics: Newton's method on f_int(u) = f with the consistent tangent
//   K_T = int Grad N_a . S Grad N_b delta_ij + dE_ai : C : dE_bj  dV
// (geometric plus material stiffness; symmetric for these laws), in load increments, an
// increment cut in half when Newton fails. Dynamics: the generalised-alpha method (Chung &
// Hulbert 1993) with Newton on every step; rho_infinity = 1 is Newmark's trapezoidal rule
// (average acceleration, no numerical dissipation). Optional Rayleigh damping
// C = alpha M + beta K0 with K0 the stiffness at u = 0. Each Newton iteration factorises
// its matrix with the project's sparse direct solver (MUMPS, fem/direct_solver.h).
//
// Vectors are PETSc vectors in the DoF layout of `body()`; Eigen::VectorXd ones are
// node-ordered (row node * dim + component, ElasticBody::to_nodal). Collective over the
// body's communicator.

#include "fem/elastic_body.h"
#include "fem/hyperelastic_material.h"

#include <Eigen/Dense>
#include <memory>

namespace chipflex::fem
{
struct NewtonOptions
{
  /// Converged when |r| <= tolerance * max(|f|, |f_int|) over the free DoFs (r the
  /// residual, f the external load of the increment or step), or when the last Newton
  /// correction was below increment_tolerance * |u|: a slender body's residual stalls
  /// at round-off (~1e-8 of a tip load on a 100:1 beam, whose axial stiffness is 1e4
  /// times its bending stiffness) after Newton has converged quadratically.
  double tolerance = 1e-9;
  double increment_tolerance = 1e-10;
  unsigned int max_iterations = 25;
};

/// What a static solve took.
struct StaticSolveStatistics
{
  unsigned int increments = 0;        ///< load increments, after any cuts
  unsigned int newton_iterations = 0; ///< total
};

template <int dim>
class NonlinearElasticBody
{
public:
  using DofVector = dealii::PETScWrappers::MPI::Vector;

  /// Builds and assembles the linear model (mass, K0) of `mesh`; `mesh` must outlive this.
  /// @param degree element degree, 1 or 2 (second-order meshes: curved cells with 2)
  /// @param clamp_group boundary group whose nodes are fixed; empty: free-free (statics
  ///        then needs a self-equilibrated load and is refused)
  NonlinearElasticBody(const GmshMeshData& mesh, const Material& material, HyperelasticModel model,
                       unsigned int degree, const std::string& clamp_group, MPI_Comm communicator,
                       NewtonOptions newton = {});

  const ElasticBody<dim>& body() const { return *linear; }
  HyperelasticModel model() const { return model_; }

  /// Internal forces f_int(u) (clamped DoFs zeroed) into `internal_force` if given, the
  /// tangent K_T(u) into tangent_matrix() if `tangent`; returns the strain energy.
  double assemble(const DofVector& u, DofVector* internal_force, bool tangent);
  double strain_energy(const DofVector& u) { return assemble(u, nullptr, false); }
  const dealii::PETScWrappers::MPI::SparseMatrix& tangent_matrix() const { return tangent_; }

  /// Static equilibrium under the dead load `force` (e.g. body().load_vector(load)),
  /// starting from u = 0 in `increments` equal load increments. Throws std::runtime_error
  /// when an increment still fails after 8 cuts.
  DofVector solve_static(const DofVector& force, unsigned int increments = 10,
                         StaticSolveStatistics* statistics = nullptr);
  /// The same for a load case; returns node-ordered displacements on every process.
  Eigen::VectorXd solve_static(const LoadCase& load, unsigned int increments = 10,
                               StaticSolveStatistics* statistics = nullptr);

  // ---- dynamics -------------------------------------------------------------------
  struct DynamicsOptions
  {
    double rho_infinity = 1;       ///< 0..1; 1: trapezoidal rule (no numerical damping)
    double rayleigh_mass = 0;      ///< alpha, 1/s
    double rayleigh_stiffness = 0; ///< beta, s (times K0)
  };
  /// Initial state u0, v0 (clamped DoFs zero) under the load `force`; the initial
  /// acceleration solves M a0 = force - f_int(u0) - C v0.
  void start_dynamics(const DynamicsOptions& options, const DofVector& u0, const DofVector& v0,
                      const DofVector& force);
  /// One step of size dt to t + dt; `force` is the load at t + dt (the one at t is the
  /// previous step's). Returns the Newton iterations it took. A step on which Newton fails
  /// is split in halves (up to 64 parts); std::runtime_error beyond that.
  unsigned int step(double dt, const DofVector& force);
  const DofVector& displacement() const { return u_; }
  const DofVector& velocity() const { return v_; }
  const DofVector& acceleration() const { return a_; }
  /// The load of the last step (or of start_dynamics), at the current time.
  const DofVector& last_force() const { return force_; }
  /// Restores a state saved from displacement(), velocity(), acceleration() and the load,
  /// with the options start_dynamics() was given.
  void set_state(const DynamicsOptions& options, const DofVector& u, const DofVector& v,
                 const DofVector& a, const DofVector& force);
  double kinetic_energy() const;

private:
  unsigned int step_or_split(double dt, const DofVector& force, unsigned int depth);
  /// One generalised-alpha step; the Newton iterations, or -1 (state unchanged) if Newton
  /// fails.
  int try_step(double dt, const DofVector& force);

  std::unique_ptr<ElasticBody<dim>> linear;
  HyperelasticModel model_;
  NewtonOptions newton_;
  double lambda_, mu_;
  dealii::PETScWrappers::MPI::SparseMatrix tangent_;
  /// Dynamics: parameters and state.
  DynamicsOptions dynamics_;
  DofVector u_, v_, a_, force_, internal_force_;
};
} // namespace chipflex::fem
