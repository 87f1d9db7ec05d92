#include "fem/elastic_body.h"

#include "common/atomic_output.h"
#include "common/input_error.h"
#include "fem/petsc_check.h"
#include "fem/petsc_matrix_setup.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_fe_field.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <fstream>
#include <set>

namespace chipflex::fem
{
template <int dim>
ElasticBody<dim>::ElasticBody(const GmshMeshData& mesh_, const Material& material_,
                              unsigned int degree_, const std::string& clamp_group_,
                              MPI_Comm communicator_)
    : mesh(mesh_), material(material_), degree(degree_), clamp_group(clamp_group_),
      communicator(communicator_), n_processes(Utilities::MPI::n_mpi_processes(communicator_)),
      this_process(Utilities::MPI::this_mpi_process(communicator_))
{
  material.check();
  if (degree != 1 && degree != 2)
    throw InputError("--degree", "must be 1 or 2, got " + std::to_string(degree));
  if (mesh.dim != dim)
    throw InputError(mesh.path, "expected a " + std::to_string(dim) + "D mesh");
  if (!clamp_group.empty())
  {
    mesh.require_group(clamp_group, "--clamp");
    if (!mesh.face_groups.count(clamp_group))
      throw InputError(mesh.path, "--clamp needs a boundary group (dimension " +
                                      std::to_string(dim - 1) + "); '" + clamp_group +
                                      "' holds cells");
  }
}

// Gmsh orders quadrilateral and hexahedron vertices counter-clockwise, deal.II
// lexicographically; simplices use the same order in both.
template <int dim>
void ElasticBody<dim>::build_triangulation()
{
  std::vector<Point<dim>> vertices(mesh.vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v)
    for (int d = 0; d < dim; ++d)
      vertices[v][d] = mesh.vertices[v][d];
  static const unsigned int quad[] = {0, 1, 3, 2}, hex[] = {0, 1, 3, 2, 4, 5, 7, 6};
  std::vector<CellData<dim>> cells(mesh.cells.size(), CellData<dim>(mesh.cells[0].size()));
  for (std::size_t c = 0; c < cells.size(); ++c)
    for (std::size_t v = 0; v < mesh.cells[c].size(); ++v)
      cells[c].vertices[v] =
          mesh.simplex ? mesh.cells[c][v] : mesh.cells[c][dim == 2 ? quad[v] : hex[v]];
  try
  {
    GridTools::invert_all_negative_measure_cells(vertices, cells);
    if (!mesh.simplex)
      GridTools::consistently_order_cells(cells);
    triangulation.create_triangulation(vertices, cells, SubCellData());
  }
  catch (const std::exception& e)
  {
    throw InputError(mesh.path, "cannot build a valid triangulation (degenerate or "
                                "inconsistent cells)");
  }
  // Contiguous blocks of cells per process: gmsh numbers cells coherently in space.
  const auto n_cells = triangulation.n_active_cells();
  for (const auto& cell : triangulation.active_cell_iterators())
    cell->set_subdomain_id(static_cast<types::subdomain_id>(
        (static_cast<unsigned long long>(cell->active_cell_index()) * n_processes) / n_cells));
}

// deal.II 9.4 offers three ways to a mapping on given high-order node positions:
// MappingQCache (hypercube cells only), MappingQEulerian (displacements from the straight
// cell, FE_Q only) and MappingFEField (absolute positions in any vector FE field). The
// last covers quadrilaterals, hexahedra and simplices alike, so chipflex interpolates the
// gmsh nodes with it: a vector FE_Q(2) (or FE_SimplexP(2)) field whose value at each
// support point is the gmsh node there. A second-order node is matched to its support
// point by the corners of the sub-entity (edge, face, cell) whose middle both are: the
// corners where the linear shape functions do not vanish, independent of how gmsh and
// deal.II order and orient their cells.
template <int dim>
void ElasticBody<dim>::build_curved_mapping()
{
  if (!mesh.complete_second_order)
    throw InputError(mesh.path, "incomplete second-order cells (8-node quadrilaterals, 20-node "
                                "hexahedra): mesh with Mesh.SecondOrderIncomplete = 0, or "
                                "reduce --straight-sided");
  std::unique_ptr<FiniteElement<dim>> linear, quadratic;
  if (mesh.simplex)
  {
    linear = std::make_unique<FE_SimplexP<dim>>(1);
    quadratic = std::make_unique<FE_SimplexP<dim>>(2);
  }
  else
  {
    linear = std::make_unique<FE_Q<dim>>(1);
    quadratic = std::make_unique<FE_Q<dim>>(2);
  }
  geometry_fe = std::make_unique<FESystem<dim>>(*quadratic, dim);
  geometry_dof_handler.reinit(triangulation);
  geometry_dof_handler.distribute_dofs(*geometry_fe);
  geometry_positions.reinit(geometry_dof_handler.n_dofs());
  const auto& unit = quadratic->get_unit_support_points();
  std::vector<types::global_dof_index> local(geometry_fe->n_dofs_per_cell());
  for (const auto& cell : geometry_dof_handler.active_cell_iterators())
  {
    cell->get_dof_indices(local);
    for (unsigned int b = 0; b < unit.size(); ++b)
    {
      std::vector<unsigned int> key;
      for (unsigned int v = 0; v < linear->n_dofs_per_cell(); ++v)
        if (linear->shape_value(v, unit[b]) > 1e-8)
          key.push_back(cell->vertex_index(v));
      std::sort(key.begin(), key.end());
      const std::array<double, 3>* x = nullptr;
      if (key.size() == 1)
        x = &mesh.vertices[key[0]];
      else
      {
        const auto it = mesh.midpoint_nodes.find(key);
        if (it == mesh.midpoint_nodes.end())
          throw InputError(mesh.path, "a second-order cell lacks the node in the middle of "
                                      "one of its edges or faces");
        x = &it->second;
      }
      for (unsigned int c = 0; c < dim; ++c)
        geometry_positions[local[geometry_fe->component_to_system_index(c, b)]] = (*x)[c];
    }
  }
  mapping = std::make_unique<MappingFEField<dim, dim, Vector<double>>>(geometry_dof_handler,
                                                                       geometry_positions);
}

template <int dim>
void ElasticBody<dim>::setup_system()
{
  build_triangulation();
  if (mesh.simplex)
  {
    fe = std::make_unique<FESystem<dim>>(FE_SimplexP<dim>(degree), dim);
    mapping = std::make_unique<MappingFE<dim>>(FE_SimplexP<dim>(1));
  }
  else
  {
    fe = std::make_unique<FESystem<dim>>(FE_Q<dim>(degree), dim);
    mapping = std::make_unique<MappingQ<dim>>(1);
  }
  // Isoparametric: a degree-1 field on curved cells could not hold rigid rotations
  // (u = w x x is quadratic there), so linear elements keep straight-sided cells.
  if (mesh.order == 2 && degree == 2)
    build_curved_mapping();
  dof_handler.reinit(triangulation);
  dof_handler.distribute_dofs(*fe);
  DoFRenumbering::subdomain_wise(dof_handler);
  locally_owned_dofs = DoFTools::locally_owned_dofs_per_subdomain(dof_handler)[this_process];
  const IndexSet relevant =
      DoFTools::locally_relevant_dofs_per_subdomain(dof_handler)[this_process];
  cells.assign(triangulation.n_active_cells(), {});
  for (const auto& cell : dof_handler.active_cell_iterators())
    cells[cell->active_cell_index()] = cell;

  number_nodes();
  find_group_faces();
  build_skin();

  constraints.clear();
  constraints.reinit(relevant);
  if (is_clamped())
  {
    std::vector<types::global_dof_index> face_dofs;
    for (const auto& [c, f] : group_faces.at(clamp_group))
    {
      face_dofs.resize(fe->n_dofs_per_face(f));
      cells[c]->face(f)->get_dof_indices(face_dofs);
      for (auto dof : face_dofs)
        if (relevant.is_element(dof) && !constraints.is_constrained(dof))
          constraints.add_line(dof);
    }
  }
  constraints.close();

  DynamicSparsityPattern dsp(relevant);
  DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false, this_process);
  SparsityTools::distribute_sparsity_pattern(dsp, locally_owned_dofs, communicator, relevant);
  reinit_from_pattern(stiffness_matrix, dsp, locally_owned_dofs, communicator);
  // M = Ms (x) I couples equal components only: a third of K's entries, so every product
  // with M (the eigen solver's M-inner products, Newmark) reads a third of the memory.
  // The cell mass matrices hold exact zeros elsewhere, which PETSc is told to drop.
  std::vector<unsigned char> component(dof_handler.n_dofs());
  for (std::size_t k = 0; k < dof_of_node.size(); ++k)
    component[dof_of_node[k]] = k % dim;
  reinit_from_pattern(mass_matrix, dsp, locally_owned_dofs, communicator,
                      [&](auto row, auto column) { return component[row] == component[column]; });
  CHIPFLEX_PETSC_CHECK(
      MatSetOption(mass_matrix.petsc_matrix(), MAT_IGNORE_ZERO_ENTRIES, PETSC_TRUE));
}

template <int dim>
void ElasticBody<dim>::number_nodes()
{
  const auto& base = fe->base_element(0);
  const unsigned int n_base = base.n_dofs_per_cell();
  const Quadrature<dim> at_support(base.get_unit_support_points());
  FEValues<dim> fe_values(*mapping, base, at_support, update_quadrature_points);
  std::vector<types::global_dof_index> local(fe->n_dofs_per_cell());
  node_of_dof.assign(dof_handler.n_dofs(), -1);
  node_coordinates.clear();
  dof_of_node.clear();
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    cell->get_dof_indices(local);
    fe_values.reinit(typename Triangulation<dim>::cell_iterator(cell));
    for (unsigned int b = 0; b < n_base; ++b)
    {
      if (node_of_dof[local[fe->component_to_system_index(0, b)]] >= 0)
        continue;
      const int node = node_coordinates.size();
      const auto& x = fe_values.quadrature_point(b);
      node_coordinates.push_back({x[0], x[1], dim == 3 ? x[dim - 1] : 0.});
      for (unsigned int c = 0; c < dim; ++c)
      {
        const auto dof = local[fe->component_to_system_index(c, b)];
        node_of_dof[dof] = node;
        dof_of_node.push_back(dof);
      }
    }
  }
  node_block_size = dim;
  for (std::size_t k = 0; k < dof_of_node.size(); ++k)
    if (dof_of_node[k] != dof_of_node[k - k % dim] + k % dim || dof_of_node[k - k % dim] % dim)
      node_block_size = 1;
}

template <int dim>
void ElasticBody<dim>::find_group_faces()
{
  std::map<std::vector<unsigned int>, std::pair<unsigned int, unsigned int>> boundary;
  for (const auto& cell : triangulation.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
      {
        std::vector<unsigned int> key;
        for (const unsigned int v : cell->face(f)->vertex_indices())
          key.push_back(cell->face(f)->vertex_index(v));
        std::sort(key.begin(), key.end());
        boundary[key] = {cell->active_cell_index(), f};
      }
  group_faces.clear();
  node_sets.clear();
  std::vector<types::global_dof_index> face_dofs, cell_dofs(fe->n_dofs_per_cell());
  for (const auto& [name, faces] : mesh.face_groups)
  {
    std::set<int> nodes;
    for (auto key : faces)
    {
      std::sort(key.begin(), key.end());
      const auto it = boundary.find(key);
      if (it == boundary.end())
        throw InputError(mesh.path, "physical group '" + name +
                                        "' holds a face that is not on the body's boundary");
      group_faces[name].push_back(it->second);
      const auto& [c, f] = it->second;
      face_dofs.resize(fe->n_dofs_per_face(f));
      cells[c]->face(f)->get_dof_indices(face_dofs);
      for (auto dof : face_dofs)
        nodes.insert(node_of_dof[dof]);
    }
    node_sets[name].assign(nodes.begin(), nodes.end());
  }
  for (const auto& [name, cell_ids] : mesh.cell_groups)
  {
    std::set<int> nodes;
    for (auto c : cell_ids)
    {
      cells[c]->get_dof_indices(cell_dofs);
      for (auto dof : cell_dofs)
        nodes.insert(node_of_dof[dof]);
    }
    node_sets[name].assign(nodes.begin(), nodes.end());
  }
}

// The skin is every boundary face, split into linear pieces through all its nodes (with
// quadratic elements: 2 segments per edge in 2D, 8 triangles per quadrilateral face and 4
// per triangular face in 3D), so that forces reach the midside nodes too. The pieces are
// found on the lattice of the face's unit support points and turned to face outward.
template <int dim>
void ElasticBody<dim>::build_skin()
{
  skin_faces.clear();
  std::set<int> nodes;
  const auto& base = fe->base_element(0);
  const int p = degree;
  std::vector<types::global_dof_index> face_dofs;
  auto point = [&](int node)
  {
    Point<dim> x;
    for (int d = 0; d < dim; ++d)
      x[d] = node_coordinates[node][d];
    return x;
  };
  for (const auto& cell : dof_handler.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
    {
      if (!cell->face(f)->at_boundary())
        continue;
      const auto unit = base.get_unit_face_support_points(f);
      face_dofs.resize(fe->n_dofs_per_face(f));
      cell->face(f)->get_dof_indices(face_dofs);
      std::map<std::pair<int, int>, int> lattice;
      for (unsigned int k = 0; k < face_dofs.size(); ++k)
      {
        const auto [component, b] = fe->face_system_to_component_index(k, f);
        if (component != 0)
          continue;
        const int i = std::lround(unit[b][0] * p), j = dim == 3 ? std::lround(unit[b][1] * p) : 0;
        lattice[{i, j}] = node_of_dof[face_dofs[k]];
        nodes.insert(node_of_dof[face_dofs[k]]);
      }
      std::vector<std::array<int, dim>> pieces;
      auto at = [&](int i, int j) { return lattice.at({i, j}); };
      if constexpr (dim == 2)
        for (int i = 0; i < p; ++i)
          pieces.push_back({at(i, 0), at(i + 1, 0)});
      else if (cell->face(f)->reference_cell() == ReferenceCells::Quadrilateral)
        for (int i = 0; i < p; ++i)
          for (int j = 0; j < p; ++j)
          {
            pieces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            pieces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
          }
      else
        for (int i = 0; i < p; ++i)
          for (int j = 0; i + j < p; ++j)
          {
            pieces.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
            if (i + j + 2 <= p)
              pieces.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
          }
      const Point<dim> centre = cell->center();
      for (auto& piece : pieces)
      {
        Tensor<1, dim> normal, middle;
        for (int v = 0; v < dim; ++v)
          middle += point(piece[v]) / double(dim);
        if constexpr (dim == 2)
        {
          const auto t = point(piece[1]) - point(piece[0]);
          normal[0] = t[1];
          normal[1] = -t[0];
        }
        else
          normal = cross_product_3d(point(piece[1]) - point(piece[0]),
                                    point(piece[2]) - point(piece[0]));
        if (normal * (middle - Tensor<1, dim>(centre)) < 0)
          std::swap(piece[0], piece[1]);
        skin_faces.push_back(piece);
      }
    }
  skin_nodes.assign(nodes.begin(), nodes.end());
}

template <int dim>
void ElasticBody<dim>::assemble_system()
{
  const Quadrature<dim> quadrature = mesh.simplex ? Quadrature<dim>(QGaussSimplex<dim>(degree + 1))
                                                  : Quadrature<dim>(QGauss<dim>(degree + 1));
  FEValues<dim> fe_values(*mapping, *fe, quadrature,
                          update_values | update_gradients | update_JxW_values);
  const unsigned int n_base = fe->base_element(0).n_dofs_per_cell();
  const unsigned int dofs_per_cell = fe->n_dofs_per_cell();
  const double lambda = material.lame_lambda(dim), mu = material.shear_modulus(),
               rho = material.density;

  FullMatrix<double> cell_stiffness(dofs_per_cell), cell_mass(dofs_per_cell);
  std::vector<types::global_dof_index> local(dofs_per_cell);
  std::vector<unsigned int> system_index(n_base * dim);
  for (unsigned int b = 0; b < n_base; ++b)
    for (unsigned int c = 0; c < dim; ++c)
      system_index[b * dim + c] = fe->component_to_system_index(c, b);
  std::vector<Eigen::Triplet<double>> triplets;
  // The scalar element's values and gradients: the vector element is n_base copies.
  std::vector<double> value(n_base);
  std::vector<Tensor<1, dim>> grad(n_base);
  FullMatrix<double> scalar_mass(n_base);
  stiffness_matrix = 0;
  mass_matrix = 0;

  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    const bool mine = cell->subdomain_id() == this_process;
    fe_values.reinit(cell);
    cell->get_dof_indices(local);
    scalar_mass = 0;
    cell_stiffness = 0;
    for (unsigned int q = 0; q < quadrature.size(); ++q)
    {
      const double jxw = fe_values.JxW(q);
      for (unsigned int a = 0; a < n_base; ++a)
      {
        value[a] = fe_values.shape_value(system_index[a * dim], q);
        grad[a] = fe_values.shape_grad(system_index[a * dim], q);
      }
      for (unsigned int a = 0; a < n_base; ++a)
        for (unsigned int b = a; b < n_base; ++b)
        {
          scalar_mass(a, b) += rho * value[a] * value[b] * jxw;
          if (!mine)
            continue;
          // K_(a,i)(b,j) = lambda d_i N_a d_j N_b + mu d_j N_a d_i N_b
          //              + mu delta_ij grad N_a . grad N_b   (step-8)
          const double diagonal = mu * (grad[a] * grad[b]) * jxw;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              cell_stiffness(a * dim + i, b * dim + j) +=
                  (lambda * grad[a][i] * grad[b][j] + mu * grad[a][j] * grad[b][i]) * jxw +
                  (i == j ? diagonal : 0.);
        }
    }
    for (unsigned int a = 0; a < n_base; ++a)
      for (unsigned int b = a; b < n_base; ++b)
      {
        const int na = node_of_dof[local[system_index[a * dim]]],
                  nb = node_of_dof[local[system_index[b * dim]]];
        triplets.emplace_back(na, nb, scalar_mass(a, b));
        if (a != b)
          triplets.emplace_back(nb, na, scalar_mass(a, b));
      }
    if (!mine)
      continue;
    // Symmetric completion, then to the system's local numbering.
    cell_mass = 0;
    FullMatrix<double> k_system(dofs_per_cell);
    for (unsigned int a = 0; a < n_base; ++a)
      for (unsigned int b = 0; b < n_base; ++b)
        for (unsigned int i = 0; i < dim; ++i)
        {
          const unsigned int ia = system_index[a * dim + i];
          if (a <= b)
            cell_mass(ia, system_index[b * dim + i]) = scalar_mass(a, b);
          else
            cell_mass(ia, system_index[b * dim + i]) = scalar_mass(b, a);
          for (unsigned int j = 0; j < dim; ++j)
            k_system(ia, system_index[b * dim + j]) =
                a <= b ? cell_stiffness(a * dim + i, b * dim + j)
                       : cell_stiffness(b * dim + j, a * dim + i);
        }
    constraints.distribute_local_to_global(k_system, local, stiffness_matrix);
    constraints.distribute_local_to_global(cell_mass, local, mass_matrix);
  }
  stiffness_matrix.compress(VectorOperation::add);
  mass_matrix.compress(VectorOperation::add);

  // Clamped DoFs keep a unit-free diagonal entry in K and M; scaling their mass entry down
  // moves the spurious eigenvalues K_ii / M_ii far above any mode we look for.
  std::vector<std::pair<types::global_dof_index, double>> clamped;
  for (const auto dof : locally_owned_dofs)
    if (constraints.is_constrained(dof))
      clamped.emplace_back(dof, mass_matrix.diag_element(dof));
  for (const auto& [dof, diagonal] : clamped)
    mass_matrix.set(dof, dof, 1e-8 * diagonal);
  mass_matrix.compress(VectorOperation::insert);

  scalar_mass_matrix.resize(n_nodes(), n_nodes());
  scalar_mass_matrix.setFromTriplets(triplets.begin(), triplets.end());
}

template <int dim>
PETScWrappers::MPI::Vector ElasticBody<dim>::new_vector() const
{
  return PETScWrappers::MPI::Vector(locally_owned_dofs, communicator);
}

template <int dim>
PETScWrappers::MPI::Vector ElasticBody<dim>::load_vector(const LoadCase& load) const
{
  mesh.require_group(load.group, "the load " + load.text);
  if (!group_faces.count(load.group))
    throw InputError(load.text, "loads act on boundary groups; '" + load.group + "' holds cells");
  const auto& faces = group_faces.at(load.group);
  const Quadrature<dim - 1> quadrature =
      mesh.simplex ? Quadrature<dim - 1>(QGaussSimplex<dim - 1>(degree + 1))
                   : Quadrature<dim - 1>(QGauss<dim - 1>(degree + 1));
  FEFaceValues<dim> fe_face(*mapping, *fe, quadrature,
                            update_values | update_normal_vectors | update_JxW_values);
  double area = 0;
  for (const auto& [c, f] : faces)
  {
    fe_face.reinit(cells[c], f);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      area += fe_face.JxW(q);
  }
  auto rhs = new_vector();
  Vector<double> cell_rhs(fe->n_dofs_per_cell());
  std::vector<types::global_dof_index> local(fe->n_dofs_per_cell());
  for (const auto& [c, f] : faces)
  {
    if (cells[c]->subdomain_id() != this_process)
      continue;
    fe_face.reinit(cells[c], f);
    cell_rhs = 0;
    for (unsigned int q = 0; q < quadrature.size(); ++q)
    {
      Tensor<1, dim> traction;
      if (load.kind == LoadCase::Kind::pressure)
        traction = -1.0 * fe_face.normal_vector(q); // 1 Pa pushing into the body
      else
        for (int d = 0; d < dim; ++d)
          traction[d] = load.force[d] / area;
      for (unsigned int i = 0; i < fe->n_dofs_per_cell(); ++i)
      {
        const unsigned int component = fe->system_to_component_index(i).first;
        cell_rhs(i) += traction[component] * fe_face.shape_value(i, q) * fe_face.JxW(q);
      }
    }
    cells[c]->get_dof_indices(local);
    constraints.distribute_local_to_global(cell_rhs, local, rhs);
  }
  rhs.compress(VectorOperation::add);
  return rhs;
}

template <int dim>
Eigen::VectorXd ElasticBody<dim>::to_nodal(const PETScWrappers::MPI::Vector& v) const
{
  const Vector<double> all(v); // gathers on every process
  Eigen::VectorXd nodal(dof_of_node.size());
  for (std::size_t k = 0; k < dof_of_node.size(); ++k)
    nodal[k] = all[dof_of_node[k]];
  return nodal;
}

template <int dim>
void ElasticBody<dim>::from_nodal(const Eigen::VectorXd& nodal, PETScWrappers::MPI::Vector& v) const
{
  for (std::size_t k = 0; k < dof_of_node.size(); ++k)
    if (locally_owned_dofs.is_element(dof_of_node[k]))
      v(dof_of_node[k]) = nodal[k];
  v.compress(VectorOperation::insert);
}

template <int dim>
void ElasticBody<dim>::output_modes(const std::string& path, const Eigen::MatrixXd& modes,
                                    const std::vector<std::string>& names) const
{
  if (this_process != 0)
    return;
  std::vector<Vector<double>> fields(modes.cols(), Vector<double>(dof_handler.n_dofs()));
  DataOut<dim> data_out;
  data_out.attach_dof_handler(dof_handler);
  const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector_field(
      dim, DataComponentInterpretation::component_is_part_of_vector);
  for (int k = 0; k < modes.cols(); ++k)
  {
    for (std::size_t r = 0; r < dof_of_node.size(); ++r)
      fields[k][dof_of_node[r]] = modes(r, k);
    data_out.add_data_vector(fields[k], std::vector<std::string>(dim, names[k]),
                             DataOut<dim>::type_dof_data, vector_field);
  }
  data_out.build_patches(*mapping, degree);
  AtomicOutput output(path);
  {
    std::ofstream out(output.temporary_path());
    data_out.write_vtu(out);
    if (!out)
      throw InputError(path, "cannot write");
  }
  output.commit();
}

template class ElasticBody<2>;
template class ElasticBody<3>;
} // namespace chipflex::fem
