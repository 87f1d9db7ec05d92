// compare_with_full(): how far the reduced body is from the full FE model, statically and
// for a step load (Newmark average acceleration on both sides, the full matrix factorised
// once and reused every step).

#include "common/input_error.h"
#include "fem/direct_solver.h"
#include "fem/elastic_body.h"
#include "fem/reduce.h"
#include "mbs/floating_frame_body.h"
#include "mbs/multibody_system.h"

#include <chrono>
#include <cmath>

namespace chipflex::fem
{
namespace
{
using clock = std::chrono::steady_clock;
double seconds_since(clock::time_point t0)
{
  return std::chrono::duration<double>(clock::now() - t0).count();
}

/// Newmark's average-acceleration rule (gamma = 1/2, beta = 1/4): unconditionally stable,
/// no numerical damping. With a0 = 4/dt^2, a1 = 4/dt:
///   (K + a0 M) u' = f + M (a0 u + a1 v + a),  a' = a0 (u' - u) - a1 v - a,
///   v' = v + dt/2 (a + a').
struct NewmarkCoefficients
{
  explicit NewmarkCoefficients(double dt) : dt(dt), a0(4 / (dt * dt)), a1(4 / dt) {}
  double dt, a0, a1;
};

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

template <int dim>
CompareResult compare(const GmshMeshData& mesh, const ReducedBodyData& reduced,
                      const CompareSettings& settings)
{
  CompareResult result;
  Material material;
  material.youngs_modulus = reduced.youngs_modulus;
  material.poisson_ratio = reduced.poisson_ratio;
  material.density = reduced.density;
  material.plane_stress = reduced.model == "plane_stress";
  ElasticBody<dim> body(mesh, material, reduced.element_degree, reduced.clamp_set, MPI_COMM_WORLD);
  auto t0 = clock::now();
  body.setup_system();
  body.assemble_system();
  const double assembly_seconds = seconds_since(t0);
  if (static_cast<int>(body.n_nodes()) != reduced.n_nodes())
    throw InputError(settings.body_file, "has " + std::to_string(reduced.n_nodes()) +
                                             " nodes, the mesh gives " +
                                             std::to_string(body.n_nodes()));
  for (int i = 0; i < reduced.n_nodes(); ++i)
    for (int d = 0; d < dim; ++d)
      if (std::abs(reduced.nodes(i, d) - body.node_coordinates[i][d]) >
          1e-9 * (1 + std::abs(reduced.nodes(i, d))))
        throw InputError(settings.body_file, "its nodes do not match the mesh's");

  const LoadCase load = LoadCase::parse(settings.load, dim, "--load");
  result.group = load.group;
  const auto force = body.load_vector(load);
  const Eigen::VectorXd force_nodal = body.to_nodal(force);

  // Observation: the mean displacement of the loaded group's nodes, one row per component.
  const auto& nodes = reduced.node_sets.at(load.group);
  Eigen::MatrixXd observe = Eigen::MatrixXd::Zero(dim, reduced.psi.rows());
  for (int node : nodes)
    for (int d = 0; d < dim; ++d)
      observe(d, node * dim + d) = 1.0 / nodes.size();
  std::vector<PETScWrappers::MPI::Vector> observe_full(dim, body.new_vector());
  for (int d = 0; d < dim; ++d)
    body.from_nodal(observe.row(d).transpose(), observe_full[d]);
  auto centroid = [&](const PETScWrappers::MPI::Vector& u)
  {
    Eigen::VectorXd c(dim);
    for (int d = 0; d < dim; ++d)
      c[d] = observe_full[d] * u;
    return c;
  };

  // Time step and duration from the lowest mode: 40 steps per period, five periods.
  const double f1 = reduced.frequencies_hz.minCoeff();
  if (!(f1 > 0))
    throw InputError(settings.body_file, "has no positive frequency");
  const double dt = settings.time_step > 0 ? settings.time_step : 1 / (40 * f1);
  const double duration = settings.duration > 0 ? settings.duration : 5 / f1;
  const int n_steps = std::max(1, static_cast<int>(std::ceil(duration / dt - 1e-9)));
  if (n_steps > 2000000)
    throw InputError("--dt", "gives more than 2e6 steps");

  // ---- full model
  t0 = clock::now();
  auto u = body.new_vector();
  {
    const DirectSolver solver(1, body.stiffness_matrix, 0, body.mass_matrix, body.node_block_size);
    solver.solve(force, u);
  }
  result.static_full = centroid(u);
  const NewmarkCoefficients c(dt);
  {
    // Consistent initial acceleration: the step load acts from t = 0, M a(0) = f.
    auto v = body.new_vector(), a = body.new_vector(), u_new = body.new_vector(),
         combination = body.new_vector(), rhs = body.new_vector();
    DirectSolver(0, body.stiffness_matrix, 1, body.mass_matrix, body.node_block_size)
        .solve(force, a);
    const DirectSolver solver(1, body.stiffness_matrix, c.a0, body.mass_matrix,
                              body.node_block_size);
    u = 0;
    result.transient_full.resize(n_steps + 1, dim);
    result.transient_full.row(0) = centroid(u).transpose();
    for (int step = 1; step <= n_steps; ++step)
    {
      combination.equ(c.a0, u);
      combination.add(c.a1, v, 1.0, a);
      body.mass_matrix.vmult(rhs, combination);
      rhs += force;
      solver.solve(rhs, u_new);
      // a' = a0 (u' - u) - a1 v - a ;  v' = v + dt/2 (a + a')
      combination.equ(c.a0, u_new);
      combination.add(-c.a0, u, -c.a1, v);
      combination.add(-1.0, a);
      v.add(0.5 * dt, a, 0.5 * dt, combination);
      a = combination;
      u = u_new;
      result.transient_full.row(step) = centroid(u).transpose();
    }
  }
  result.full_seconds = assembly_seconds + seconds_since(t0);

  // ---- reduced body
  t0 = clock::now();
  const Eigen::VectorXd modal_force = reduced.psi.transpose() * force_nodal;
  const Eigen::MatrixXd observe_modal = observe * reduced.psi;
  result.static_reduced = observe_modal * reduced.stiffness_matrix.ldlt().solve(modal_force);
  result.transient_reduced = reduced_step_response<dim>(reduced, force_nodal, nodes, dt, n_steps);
  result.reduced_integrator = "mbs::FloatingFrameBody, clamped frame, generalised-alpha rho=1";
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
} // namespace

CompareResult compare_with_full(const CompareSettings& settings)
{
  const ReducedBodyData reduced = read_reduced_body(settings.body_file);
  if (reduced.clamp_set.empty())
    throw InputError(settings.body_file,
                     "is a free-free body; compare needs a clamped one (reduce with --clamp)");
  if (file_hash(settings.mesh_file) != reduced.mesh_hash)
    throw InputError(settings.mesh_file, "is not the mesh " + settings.body_file +
                                             " was reduced from (its hash differs)");
  const GmshMeshData mesh = read_gmsh_mesh(settings.mesh_file);
  if (mesh.dim != reduced.dim)
    throw InputError(settings.mesh_file, "dimension differs from the body file's");
  if (mesh.dim == 2)
    return compare<2>(mesh, reduced, settings);
  return compare<3>(mesh, reduced, settings);
}
} // namespace chipflex::fem
