// compare_with_full(): how far the reduced body is from the full FE model, statically and
// for a step load, observed at the centroid of the loaded group's nodes.

#include "compare/compare_with_full.h"

#include "common/input_error.h"
#include "common/reduced_body_file.h"
#include "common/wall_clock.h"
#include "fem/full_response.h"
#include "mbs/floating_frame_body.h"
#include "mbs/multibody_system.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace chipflex::compare
{
namespace
{
using clock = WallClock;

/// The reduced body's step response through the simulation's own body model: an
/// mbs::FloatingFrameBody with its frame clamped to ground (then M_red q'' + K_red q =
/// Psi^T f), the consistent nodal forces of the loaded group applied to its nodes, and
/// the generalised-alpha integrator at rho_infinity = 1, which is Newmark's average
/// acceleration rule with consistent initial accelerations, as on the full side.
template <int dim>
Eigen::MatrixXd reduced_step_response(const ReducedBodyData& data,
                                      const Eigen::VectorXd& nodal_force,
                                      const std::vector<int>& group, double dt, int n_steps)
{
  using Vector = typename mbs::FloatingFrameBody<dim>::Vector;
  mbs::IntegratorOptions integrator;
  integrator.rho_infinity = 1;
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
    system.step(dt);
    Vector mean = Vector::Zero();
    for (int node : group)
      mean += body.node_displacement(node) / double(group.size());
    history.row(step) = mean.transpose();
  }
  return history;
}

/// The reduced body's own static equilibrium under the load: the clamped body released
/// from rest with every mode critically damped (zeta = 1), stepped one lowest period
/// (20 steps) at a time until the loaded group's mean moves by less than 1e-10 of itself
/// over a period. Works for whatever the body file holds, linear or not.
template <int dim>
Eigen::VectorXd reduced_static_by_relaxation(const ReducedBodyData& data,
                                             const Eigen::VectorXd& nodal_force,
                                             const std::vector<int>& group, double period)
{
  using Vector = typename mbs::FloatingFrameBody<dim>::Vector;
  mbs::IntegratorOptions integrator;
  integrator.rho_infinity = 1;
  mbs::MultibodySystem<dim> system(integrator);
  mbs::FloatingFrameOptions options;
  options.damping = mbs::DampingKind::modal;
  options.modal_damping_ratio = 1;
  const int id = system.add_body(std::make_unique<mbs::FloatingFrameBody<dim>>(data, options));
  auto& body = dynamic_cast<mbs::FloatingFrameBody<dim>&>(system.body(id));
  body.clamp_to_ground();
  std::vector<Vector> forces(group.size());
  for (std::size_t i = 0; i < group.size(); ++i)
    for (int d = 0; d < dim; ++d)
      forces[i][d] = nodal_force[group[i] * dim + d];
  body.set_node_forces(group, forces);
  auto mean = [&]
  {
    Vector m = Vector::Zero();
    for (int node : group)
      m += body.node_displacement(node) / double(group.size());
    return m;
  };
  Vector last = mean();
  for (int p = 0; p < 400; ++p)
  {
    for (int s = 0; s < 20; ++s)
      system.step(period / 20);
    const Vector now = mean();
    if ((now - last).norm() <= 1e-10 * now.norm())
      return now;
    last = now;
  }
  throw std::runtime_error("compare: the reduced body does not come to rest in 400 periods");
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
  if (settings.nonlinear)
    result.static_reduced =
        dim == 2 ? Eigen::VectorXd(
                       reduced_static_by_relaxation<2>(reduced, full.nodal_force, nodes, 1 / f1))
                 : Eigen::VectorXd(
                       reduced_static_by_relaxation<3>(reduced, full.nodal_force, nodes, 1 / f1));
  else
    result.static_reduced =
        observe * reduced.psi * reduced.stiffness_matrix.ldlt().solve(modal_force);
  result.transient_reduced =
      dim == 2 ? reduced_step_response<2>(reduced, full.nodal_force, nodes, dt, n_steps)
               : reduced_step_response<3>(reduced, full.nodal_force, nodes, dt, n_steps);
  result.reduced_integrator = "mbs::FloatingFrameBody, clamped frame, generalised-alpha rho=1";
  if (settings.nonlinear)
    result.reduced_integrator += "; static: dynamic relaxation";
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
