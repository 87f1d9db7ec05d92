// compare_with_full(): how far the reduced body is from the full FE model, statically and
// for a step load, observed at the centroid of the loaded group's nodes.

#include "compare/compare_with_full.h"

#include "common/input_error.h"
#include "common/polynomial_stiffness.h"
#include "common/reduced_body_file.h"
#include "common/wall_clock.h"
#include "fem/full_response.h"
#include "mbs/floating_frame_body.h"
#include "mbs/multibody_system.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace chipflex::compare
{
namespace
{
using clock = WallClock;

/// The reduced body's step response through the simulation's own body model: an
/// mbs::FloatingFrameBody with its frame clamped to ground (then M_red q'' + K_red q =
/// Psi^T f), the consistent nodal forces of the loaded group applied to its nodes, and
/// the generalised-alpha integrator at `rho_infinity` (1: Newmark's average acceleration
/// rule with consistent initial accelerations, as on the full side), `substeps` steps of
/// dt / substeps between the recorded ones.
template <int dim>
Eigen::MatrixXd reduced_step_response(const ReducedBodyData& data,
                                      const Eigen::VectorXd& nodal_force,
                                      const std::vector<int>& group, double dt, int n_steps,
                                      double rho_infinity, int substeps)
{
  using Vector = typename mbs::FloatingFrameBody<dim>::Vector;
  mbs::IntegratorOptions integrator;
  integrator.rho_infinity = rho_infinity;
  mbs::MultibodySystem<dim> system(integrator);
  const int id = system.add_body(std::make_unique<mbs::FloatingFrameBody<dim>>(data));
  auto& body = dynamic_cast<mbs::FloatingFrameBody<dim>&>(system.body(id));
  body.clamp_to_ground();
  std::vector<Vector> forces(group.size());
  for (std::size_t i = 0; i < group.size(); ++i)
    for (int d = 0; d < dim; ++d)
      forces[i][d] = nodal_force[group[i] * dim + d];
  body.set_node_forces(group, forces);
  Eigen::MatrixXd history = Eigen::MatrixXd::Zero(n_steps + 1, dim);
  for (int step = 1; step <= n_steps; ++step)
  {
    for (int s = 0; s < substeps; ++s)
      system.step(dt / substeps);
    Vector mean = Vector::Zero();
    for (int node : group)
      mean += body.node_displacement(node) / double(group.size());
    history.row(step) = mean.transpose();
  }
  return history;
}

/// The reduced body's own static equilibrium f(q) = Psi^T f_ext, with f(q) its internal
/// force (linear K q, or the St Venant-Kirchhoff cubic with tangent K_t(q)), by Newton's
/// method in load increments, an increment halved when Newton fails. The clamped frame is
/// ground, so this is the equilibrium the simulation's body model comes to rest in. Dynamic
/// relaxation (released from rest, critically damped) reached the same point for linear
/// bodies, but for a slender nonlinear one the integrator's Newton iteration failed in it
/// (a 50:1 beam at P L^2/EI = 0.075 after 35 periods), the axial (derivative) coordinates
/// far beyond the step's resolution.
Eigen::VectorXd reduced_static_by_newton(const ReducedBodyData& data,
                                         const Eigen::VectorXd& modal_force,
                                         unsigned int increments)
{
  const int m = static_cast<int>(data.stiffness_matrix.rows());
  if (!data.nonlinear())
    return data.stiffness_matrix.ldlt().solve(modal_force);
  const PolynomialStiffness svk(data.stiffness_matrix, data.quadratic_stiffness,
                                data.cubic_stiffness);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m), trial(m), f(m), residual(m);
  Eigen::MatrixXd tangent(m, m);
  // Converged when the residual is 1e-10 of the load, or when the correction has stopped
  // shrinking at round-off (the axial coordinates are 1e4 times stiffer than the bending
  // ones on a 100:1 beam, so the residual may stall at round-off above that).
  auto newton = [&](const Eigen::VectorXd& load)
  {
    double last = std::numeric_limits<double>::infinity();
    for (int it = 0; it < 30; ++it)
    {
      svk.evaluate(trial, f, &tangent);
      residual = load - f;
      if (!residual.allFinite())
        return false;
      if (residual.norm() <= 1e-10 * std::max(load.norm(), f.norm()))
        return true;
      const Eigen::VectorXd dq = tangent.ldlt().solve(residual);
      trial += dq;
      const double size = dq.norm();
      if (size <= 1e-13 * trial.norm() || (size <= 1e-9 * trial.norm() && size >= 0.5 * last))
        return true;
      last = size;
    }
    return false;
  };
  double done = 0, increment = 1.0 / std::max(1u, increments);
  int cuts = 0;
  while (done < 1 - 1e-12)
  {
    const double size = std::min(increment, 1 - done);
    trial = q;
    if (newton((done + size) * modal_force))
    {
      q = trial;
      done += size;
    }
    else
    {
      if (++cuts > 10)
        throw SimulationError("compare: the reduced body's static Newton iteration fails at load "
                              "factor " +
                              std::to_string(done) + " even with increments of " +
                              std::to_string(size));
      increment = size / 2;
    }
  }
  return q;
}
} // namespace

CompareResult compare_with_full(const CompareSettings& settings)
{
  const ReducedBodyData reduced = read_reduced_body(settings.body_file);
  if (reduced.clamp_set.empty())
    throw InputError(settings.body_file,
                     "is a free-free body; compare needs a clamped one (reduce with --clamp)");

  // Time step and duration from the lowest mode: 40 steps per period, five periods.
  const double f1 = reduced.frequencies_hz.minCoeff();
  if (!(f1 > 0))
    throw InputError(settings.body_file, "has no positive frequency");
  const double dt = settings.time_step > 0 ? settings.time_step : 1 / (40 * f1);
  const double duration = settings.duration > 0 ? settings.duration : 5 / f1;
  const int n_steps = std::max(1, static_cast<int>(std::ceil(duration / dt - 1e-9)));
  if (n_steps > 2000000)
    throw InputError("--dt", "gives more than 2e6 steps");

  CompareResult result;
  fem::FullResponseSettings full_settings;
  full_settings.mesh_file = settings.mesh_file;
  full_settings.body_file = settings.body_file;
  full_settings.load = settings.load;
  full_settings.time_step = dt;
  full_settings.n_steps = n_steps;
  full_settings.nonlinear = settings.nonlinear;
  full_settings.material_model =
      fem::parse_hyperelastic_model(settings.material_model, "--material");
  full_settings.load_increments = settings.load_increments;
  const fem::FullResponse full = fem::full_response(reduced, full_settings);
  result.group = full.group;
  result.static_full = full.static_centroid;
  result.transient_full = full.transient;
  result.full_seconds = full.seconds;

  const auto t0 = clock::now();
  const int dim = reduced.dim;
  const auto& nodes = reduced.node_sets.at(full.group);
  Eigen::MatrixXd observe = Eigen::MatrixXd::Zero(dim, reduced.psi.rows());
  for (int node : nodes)
    for (int d = 0; d < dim; ++d)
      observe(d, node * dim + d) = 1.0 / nodes.size();
  const Eigen::VectorXd modal_force = reduced.psi.transpose() * full.nodal_force;
  result.static_reduced =
      observe * reduced.psi *
      (settings.nonlinear ? reduced_static_by_newton(reduced, modal_force, settings.load_increments)
                          : Eigen::VectorXd(reduced.stiffness_matrix.ldlt().solve(modal_force)));
  // The same rule as the full side's transient; if it fails on the reduced side (the
  // trapezoidal rule's instability for nonlinear bodies, fem/full_response.cc), the next
  // more dissipative one, so that a failure is a one-line error only after rho = 0.5.
  std::string failure;
  double rho = full.rho_infinity;
  int substeps = 1;
  // The reduced transient costs milliseconds, so after the rules with the full side's step
  // it tries them again with the step cut into 2, 4, ... 64 sub-steps (recorded every dt).
  // The full side's step first: sub-steps change the rule's phase error, and with it the
  // comparison (on the 50:1 beam at P L^2/EI = 0.075, 4.7 % with rho = 1 and sub-steps
  // against 0.35 % with rho = 0.9 and the full side's step).
  for (substeps = 1; substeps <= 64 && (substeps == 1 || !failure.empty()); substeps *= 2)
    for (const double candidate : {1.0, 0.9, 0.7, 0.5})
    {
      if (candidate > full.rho_infinity)
        continue;
      rho = candidate;
      try
      {
        result.transient_reduced = dim == 2
                                       ? reduced_step_response<2>(reduced, full.nodal_force, nodes,
                                                                  dt, n_steps, rho, substeps)
                                       : reduced_step_response<3>(reduced, full.nodal_force, nodes,
                                                                  dt, n_steps, rho, substeps);
        failure.clear();
        break;
      }
      catch (const SimulationError& e)
      {
        failure = e.what();
      }
    }
  substeps /= 2; // the loop's last increment
  if (!failure.empty())
    throw SimulationError("compare: the reduced body's transient fails even with rho_infinity "
                          "0.5 and 64 sub-steps (" +
                          failure + "); try a smaller --dt");
  result.rho_infinity = full.rho_infinity;
  result.reduced_rho_infinity = rho;
  std::ostringstream integrator;
  integrator << "mbs::FloatingFrameBody, clamped frame, generalised-alpha rho=" << rho;
  if (substeps > 1)
    integrator << ", " << substeps << " sub-steps per step";
  result.reduced_integrator = integrator.str();
  if (settings.nonlinear)
    result.reduced_integrator += "; static: Newton in load increments";
  result.reduced_seconds = seconds_since(t0);

  result.time.resize(n_steps + 1);
  for (int step = 0; step <= n_steps; ++step)
    result.time[step] = step * dt;
  result.static_rel_error =
      (result.static_reduced - result.static_full).norm() / result.static_full.norm();
  double largest_full = 0, largest_difference = 0;
  for (int step = 0; step <= n_steps; ++step)
  {
    largest_full = std::max(largest_full, result.transient_full.row(step).norm());
    largest_difference =
        std::max(largest_difference,
                 (result.transient_reduced.row(step) - result.transient_full.row(step)).norm());
  }
  result.transient_rel_error = largest_difference / largest_full;
  return result;
}
} // namespace chipflex::compare
