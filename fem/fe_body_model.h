#pragma once
// The full nonlinear FE body (fem/nonlinear_elastic_body.h) behind a deal.II-free face, for
// the `fe` body kind of case files and anything else outside fem/ that steps it: nodal
// quantities are node-ordered Eigen vectors (row node * dim + component) in the mesh's
// coordinates. Serial (MPI_COMM_SELF); the first model initialises MPI and PETSc if the
// program has not (and finalises them at exit).

#include "fem/hyperelastic_model.h"
#include "fem/material.h"

#include <Eigen/Core>
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace chipflex::fem
{
struct FeBodySettings
{
  std::string mesh_file; ///< gmsh .msh, as for `chipflex reduce`
  Material material;
  HyperelasticModel model = HyperelasticModel::st_venant_kirchhoff;
  unsigned int degree = 2;  ///< 1 or 2 (second-order meshes: curved cells with 2)
  std::string clamp_group;  ///< boundary group held fixed; empty: a free body
  double rho_infinity = 1;  ///< generalised-alpha spectral radius, 0..1 (1: trapezoidal)
  double rayleigh_mass = 0; ///< C = alpha M + beta K0
  double rayleigh_stiffness = 0;
};

template <int dim>
class FeBodyModel
{
public:
  /// Reads the mesh, builds and assembles the model; InputError for bad input.
  explicit FeBodyModel(const FeBodySettings& settings);
  ~FeBodyModel();
  FeBodyModel(const FeBodyModel&) = delete;
  FeBodyModel& operator=(const FeBodyModel&) = delete;

  int n_nodes() const;
  /// Reference position of node n (mesh coordinates).
  Eigen::Matrix<double, dim, 1> node_position(int node) const;
  /// Boundary nodes and the skin's linear pieces (node numbers, outward: ElasticBody).
  const std::vector<int>& skin_nodes() const;
  const std::vector<std::array<int, dim>>& skin_faces() const;
  /// A physical group's nodes; InputError naming the mesh if it has no such group.
  const std::vector<int>& node_set(const std::string& name) const;
  bool has_node_set(const std::string& name) const;
  /// Row sums of the consistent mass matrix (per node, kg; 2D per metre): the consistent
  /// load of a uniform acceleration g on node n is node_masses()[n] g.
  const Eigen::VectorXd& node_masses() const;
  double mass() const { return node_masses().sum(); }
  int n_dofs() const;

  /// Dynamics from rest at u = 0 under the nodal forces f (node-ordered).
  void start(const Eigen::VectorXd& nodal_force);
  /// One implicit step to t + dt with the nodal forces f at t + dt (dead loads). Returns the
  /// Newton iterations it took.
  int step(double dt, const Eigen::VectorXd& nodal_force);
  Eigen::VectorXd displacement() const; ///< node-ordered
  Eigen::VectorXd velocity() const;
  double kinetic_energy() const;
  double strain_energy() const;

  /// Static equilibrium under dead nodal forces, in `increments` load increments.
  Eigen::VectorXd solve_static(const Eigen::VectorXd& nodal_force, unsigned int increments = 10);

  /// The dynamic state (u, v, a and the last step's load); restore(state()) is exact.
  std::vector<double> state() const;
  void restore(const std::vector<double>& state);

private:
  struct Impl;
  std::unique_ptr<Impl> impl;
};
} // namespace chipflex::fem
