#pragma once
// The finite-element model of one elastic body (deal.II; include only from fem/ and apps/):
// triangulation built from a gmsh mesh, vector-valued FE_Q / FE_SimplexP elasticity,
// consistent mass, clamp constraints, named node sets, the skin, and load vectors.
//
// Matrices are PETSc MPI matrices. Every process holds the whole (small, serial)
// triangulation; cells are split into contiguous blocks of the gmsh cell order, one per
// process (step-17's approach), and each process assembles its own block.
//
// FE "nodes" are the unique support points of the scalar element (with quadratic
// elements they include the midside nodes). Nodes are numbered in the order in which a
// walk over the cells meets them, which does not depend on the number of processes, so the
// body file is the same under `mpirun -np N`.

#include "fem/gmsh_reader.h"
#include "fem/load_case.h"
#include "fem/material.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/vector.h>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace chipflex::fem
{
using namespace dealii;

template <int dim>
class ElasticBody
{
public:
  /// @param degree element degree, 1 or 2
  /// @param clamp_group physical group whose nodes are fixed; empty: free-free
  ElasticBody(const GmshMeshData& mesh, const Material& material, unsigned int degree,
              const std::string& clamp_group, MPI_Comm communicator);

  /// Triangulation, DoFs, partition, node map, named sets, skin, clamp constraints.
  void setup_system();
  /// Stiffness K and consistent mass M (PETSc, DoF numbering) and the scalar mass matrix
  /// Ms (Eigen, node numbering, the same on every process).
  void assemble_system();

  /// Consistent nodal forces of a load case (clamped DoFs zeroed).
  PETScWrappers::MPI::Vector load_vector(const LoadCase& load) const;
  /// A distributed vector in this body's layout, zero.
  PETScWrappers::MPI::Vector new_vector() const;

  /// Distributed DoF vector -> node-ordered vector (row node*dim + component), gathered on
  /// every process; and back.
  Eigen::VectorXd to_nodal(const PETScWrappers::MPI::Vector& v) const;
  void from_nodal(const Eigen::VectorXd& nodal, PETScWrappers::MPI::Vector& v) const;

  /// ParaView file of mode shapes (node-ordered columns); call on every process, rank 0 writes.
  void output_modes(const std::string& path, const Eigen::MatrixXd& modes,
                    const std::vector<std::string>& names) const;

  unsigned int n_nodes() const { return node_coordinates.size(); }
  bool is_clamped() const { return !clamp_group.empty(); }

  const GmshMeshData& mesh;
  const Material material;
  const unsigned int degree;
  const std::string clamp_group;
  MPI_Comm communicator;
  const unsigned int n_processes, this_process;

  Triangulation<dim> triangulation;
  /// Second-order meshes: the vector FE_Q(2) / FE_SimplexP(2) field of the node positions
  /// that `mapping` interpolates; declared before it, which refers to them, (empty for linear
  /// meshes).
  std::unique_ptr<FESystem<dim>> geometry_fe;
  DoFHandler<dim> geometry_dof_handler;
  Vector<double> geometry_positions;
  /// The geometry: straight-sided (MappingQ(1), MappingFE(P1)) for a linear mesh; for a
  /// second-order gmsh mesh the isoparametric MappingFEField on the gmsh nodes, so that
  /// curved cells stay curved (fem/elastic_body.cc, build_curved_mapping).
  std::unique_ptr<Mapping<dim>> mapping;
  std::unique_ptr<FESystem<dim>> fe;
  DoFHandler<dim> dof_handler;
  IndexSet locally_owned_dofs;
  AffineConstraints<double> constraints; ///< the clamp: u = 0

  PETScWrappers::MPI::SparseMatrix stiffness_matrix;
  PETScWrappers::MPI::SparseMatrix mass_matrix;
  Eigen::SparseMatrix<double> scalar_mass_matrix; ///< Ms, n_nodes x n_nodes

  std::vector<std::array<double, 3>> node_coordinates;
  std::vector<types::global_dof_index> dof_of_node; ///< index node*dim + component
  std::vector<int> node_of_dof;                     ///< -1 never happens after setup
  /// dim when every node's DoFs are dim consecutive indices from a multiple of dim (the
  /// sparse direct solver then orders nodes, not DoFs: fem/direct_solver.h), else 1.
  unsigned int node_block_size = 1;
  std::vector<typename DoFHandler<dim>::active_cell_iterator> cells; ///< by active index
  std::map<std::string, std::vector<int>> node_sets;
  std::vector<int> skin_nodes;
  std::vector<std::array<int, dim>> skin_faces; ///< linear pieces, outward

private:
  void build_triangulation();
  void build_curved_mapping();
  void number_nodes();
  void find_group_faces();
  void build_skin();

  /// Physical group name -> boundary faces (active cell index, face number).
  std::map<std::string, std::vector<std::pair<unsigned int, unsigned int>>> group_faces;
};
} // namespace chipflex::fem
