// full_response(): the full FE model's static and step-load responses (fem/full_response.h).

#include "fem/full_response.h"

#include "common/input_error.h"
#include "common/wall_clock.h"
#include "fem/direct_solver.h"
#include "fem/elastic_body.h"
#include "fem/gmsh_reader.h"
#include "fem/nonlinear_elastic_body.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace chipflex::fem
{
namespace
{
using clock = WallClock;

/// Newmark's average-acceleration rule (gamma = 1/2, beta = 1/4): unconditionally stable,
/// no numerical damping. With a0 = 4/dt^2, a1 = 4/dt:
///   (K + a0 M) u' = f + M (a0 u + a1 v + a),  a' = a0 (u' - u) - a1 v - a,
///   v' = v + dt/2 (a + a').
struct NewmarkCoefficients
{
  explicit NewmarkCoefficients(double dt) : dt(dt), a0(4 / (dt * dt)), a1(4 / dt) {}
  double dt, a0, a1;
};

template <int dim>
FullResponse respond(const GmshMeshData& mesh, const ReducedBodyData& reduced,
                     const FullResponseSettings& settings)
{
  FullResponse result;
  Material material;
  material.youngs_modulus = reduced.youngs_modulus;
  material.poisson_ratio = reduced.poisson_ratio;
  material.density = reduced.density;
  material.plane_stress = reduced.model == "plane_stress";
  const auto t0 = clock::now();
  std::unique_ptr<NonlinearElasticBody<dim>> nonlinear;
  std::unique_ptr<ElasticBody<dim>> linear;
  if (settings.nonlinear)
    nonlinear = std::make_unique<NonlinearElasticBody<dim>>(mesh, material, settings.material_model,
                                                            reduced.element_degree,
                                                            reduced.clamp_set, MPI_COMM_WORLD);
  else
  {
    linear = std::make_unique<ElasticBody<dim>>(mesh, material, reduced.element_degree,
                                                reduced.clamp_set, MPI_COMM_WORLD);
    linear->setup_system();
    linear->assemble_system();
  }
  const ElasticBody<dim>& body = nonlinear ? nonlinear->body() : *linear;
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
  result.nodal_force = body.to_nodal(force);

  // Observation: the mean displacement of the loaded group's nodes, one row per component.
  const auto& nodes = reduced.node_sets.at(load.group);
  std::vector<PETScWrappers::MPI::Vector> observe(dim, body.new_vector());
  for (int d = 0; d < dim; ++d)
  {
    Eigen::VectorXd row = Eigen::VectorXd::Zero(reduced.psi.rows());
    for (int node : nodes)
      row[node * dim + d] = 1.0 / nodes.size();
    body.from_nodal(row, observe[d]);
  }
  auto centroid = [&](const PETScWrappers::MPI::Vector& u)
  {
    Eigen::VectorXd c(dim);
    for (int d = 0; d < dim; ++d)
      c[d] = observe[d] * u;
    return c;
  };

  if (nonlinear)
  {
    PETScWrappers::MPI::Vector u;
    try
    {
      u = nonlinear->solve_static(force, settings.load_increments);
    }
    catch (const SimulationError&)
    {
      throw;
    }
    catch (const std::runtime_error& e)
    {
      throw SimulationError(std::string("compare: the full model's static solution: ") + e.what());
    }
    result.static_centroid = centroid(u);
    // The step load from rest: the trapezoidal rule (generalised-alpha, rho = 1), as the
    // linear Newmark rule below. It is not unconditionally stable for a nonlinear body
    // (Simo & Tarnow 1992): the axial modes of a slender beam, thousands of times above
    // the step's resolution, exchange energy with the bending ones through the
    // geometric coupling, gain it, and Newton then fails in every split of the step
    // (a 50:1 beam at P L^2/EI = 3). Then the transient is run again from rest with
    // numerical dissipation, rho_infinity = 0.9, 0.7, 0.5, which damps the unresolved
    // modes and leaves the resolved ones (40 steps per period) nearly untouched.
    const double rhos[] = {1, 0.9, 0.7, 0.5};
    std::string failure;
    for (const double rho : rhos)
    {
      auto zero = body.new_vector();
      zero = 0;
      typename NonlinearElasticBody<dim>::DynamicsOptions options;
      options.rho_infinity = rho;
      nonlinear->start_dynamics(options, zero, zero, force);
      result.transient.resize(settings.n_steps + 1, dim);
      result.transient.row(0) = centroid(zero).transpose();
      try
      {
        for (int step = 1; step <= settings.n_steps; ++step)
        {
          nonlinear->step(settings.time_step, force);
          result.transient.row(step) = centroid(nonlinear->displacement()).transpose();
        }
      }
      catch (const std::runtime_error& e)
      {
        failure = e.what();
        continue;
      }
      result.rho_infinity = rho;
      result.seconds = seconds_since(t0);
      return result;
    }
    throw SimulationError("compare: the full model's transient fails even with rho_infinity "
                          "0.5 (" +
                          failure + "); try a smaller --dt");
  }

  auto u = body.new_vector();
  {
    const DirectSolver solver(1, body.stiffness_matrix, 0, body.mass_matrix, body.node_block_size);
    solver.solve(force, u);
  }
  result.static_centroid = centroid(u);

  const double dt = settings.time_step;
  const NewmarkCoefficients c(dt);
  // Consistent initial acceleration: the step load acts from t = 0, M a(0) = f.
  auto v = body.new_vector(), a = body.new_vector(), u_new = body.new_vector(),
       combination = body.new_vector(), rhs = body.new_vector();
  DirectSolver(0, body.stiffness_matrix, 1, body.mass_matrix, body.node_block_size).solve(force, a);
  const DirectSolver solver(1, body.stiffness_matrix, c.a0, body.mass_matrix, body.node_block_size);
  u = 0;
  result.transient.resize(settings.n_steps + 1, dim);
  result.transient.row(0) = centroid(u).transpose();
  for (int step = 1; step <= settings.n_steps; ++step)
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
    result.transient.row(step) = centroid(u).transpose();
  }
  result.seconds = seconds_since(t0);
  return result;
}
} // namespace

FullResponse full_response(const ReducedBodyData& body, const FullResponseSettings& settings)
{
  if (!(settings.time_step > 0) || settings.n_steps < 1)
    throw std::invalid_argument("full_response: time step and step count must be positive");
  if (file_hash(settings.mesh_file) != body.mesh_hash)
    throw InputError(settings.mesh_file, "is not the mesh " + settings.body_file +
                                             " was reduced from (its hash differs)");
  const GmshMeshData mesh = read_gmsh_mesh(settings.mesh_file);
  if (mesh.dim != body.dim)
    throw InputError(settings.mesh_file, "dimension differs from the body file's");
  if (mesh.dim == 2)
    return respond<2>(mesh, body, settings);
  return respond<3>(mesh, body, settings);
}
} // namespace chipflex::fem
