// FeBodyModel: the nonlinear FE body behind a deal.II-free interface (fem/fe_body_model.h).

#include "fem/fe_body_model.h"

#include "common/input_error.h"
#include "fem/gmsh_reader.h"
#include "fem/nonlinear_elastic_body.h"

#include <mpi.h>
#include <petscsys.h>

namespace chipflex::fem
{
namespace
{
/// MPI and PETSc for programs that did not start them (`chipflex run` is not an MPI
/// program): started on first use, finalised at exit, after every model is gone.
void ensure_petsc()
{
  struct Session
  {
    Session()
    {
      int mpi_started = 0;
      MPI_Initialized(&mpi_started);
      if (!mpi_started)
      {
        MPI_Init(nullptr, nullptr);
        started_mpi = true;
      }
      PetscBool petsc_started = PETSC_FALSE;
      PetscInitialized(&petsc_started);
      if (!petsc_started)
      {
        PetscInitializeNoArguments();
        started_petsc = true;
      }
    }
    ~Session()
    {
      if (started_petsc)
        PetscFinalize();
      if (started_mpi)
        MPI_Finalize();
    }
    bool started_mpi = false, started_petsc = false;
  };
  static Session session;
}
} // namespace

template <int dim>
struct FeBodyModel<dim>::Impl
{
  explicit Impl(const FeBodySettings& s)
      : mesh(read_gmsh_mesh(s.mesh_file)), model(check_dimension(mesh, s.mesh_file), s.material,
                                                 s.model, s.degree, s.clamp_group, MPI_COMM_SELF)
  {
    // A free body (no clamp group) is fine for dynamics: the mass term keeps every Newton
    // matrix regular.
    const auto& b = model.body();
    node_masses = b.scalar_mass_matrix * Eigen::VectorXd::Ones(b.n_nodes());
    options.rho_infinity = s.rho_infinity;
    options.rayleigh_mass = s.rayleigh_mass;
    options.rayleigh_stiffness = s.rayleigh_stiffness;
  }
  static const GmshMeshData& check_dimension(const GmshMeshData& mesh, const std::string& path)
  {
    if (mesh.dim != dim)
      throw InputError(path, "a " + std::to_string(mesh.dim) + "D mesh for a " +
                                 std::to_string(dim) + "D body");
    return mesh;
  }
  PETScWrappers::MPI::Vector to_dofs(const Eigen::VectorXd& nodal) const
  {
    const auto& b = model.body();
    if (nodal.size() != static_cast<Eigen::Index>(b.n_nodes()) * dim)
      throw std::invalid_argument("FeBodyModel: nodal vector of the wrong size");
    auto v = b.new_vector();
    b.from_nodal(nodal, v);
    b.constraints.set_zero(v);
    return v;
  }

  GmshMeshData mesh;
  NonlinearElasticBody<dim> model;
  typename NonlinearElasticBody<dim>::DynamicsOptions options;
  Eigen::VectorXd node_masses;
};

template <int dim>
FeBodyModel<dim>::FeBodyModel(const FeBodySettings& settings)
{
  ensure_petsc();
  impl = std::make_unique<Impl>(settings);
}

template <int dim>
FeBodyModel<dim>::~FeBodyModel() = default;

template <int dim>
int FeBodyModel<dim>::n_nodes() const
{
  return impl->model.body().n_nodes();
}

template <int dim>
int FeBodyModel<dim>::n_dofs() const
{
  return impl->model.body().dof_handler.n_dofs();
}

template <int dim>
Eigen::Matrix<double, dim, 1> FeBodyModel<dim>::node_position(int node) const
{
  Eigen::Matrix<double, dim, 1> x;
  for (int d = 0; d < dim; ++d)
    x[d] = impl->model.body().node_coordinates[node][d];
  return x;
}

template <int dim>
const std::vector<int>& FeBodyModel<dim>::skin_nodes() const
{
  return impl->model.body().skin_nodes;
}

template <int dim>
const std::vector<std::array<int, dim>>& FeBodyModel<dim>::skin_faces() const
{
  return impl->model.body().skin_faces;
}

template <int dim>
bool FeBodyModel<dim>::has_node_set(const std::string& name) const
{
  return impl->model.body().node_sets.count(name) > 0;
}

template <int dim>
const std::vector<int>& FeBodyModel<dim>::node_set(const std::string& name) const
{
  const auto& sets = impl->model.body().node_sets;
  const auto it = sets.find(name);
  if (it == sets.end())
    throw InputError(impl->mesh.path, "has no physical group '" + name + "'");
  return it->second;
}

template <int dim>
const Eigen::VectorXd& FeBodyModel<dim>::node_masses() const
{
  return impl->node_masses;
}

template <int dim>
void FeBodyModel<dim>::start(const Eigen::VectorXd& nodal_force)
{
  auto zero = impl->model.body().new_vector();
  zero = 0;
  impl->model.start_dynamics(impl->options, zero, zero, impl->to_dofs(nodal_force));
}

template <int dim>
int FeBodyModel<dim>::step(double dt, const Eigen::VectorXd& nodal_force)
{
  return impl->model.step(dt, impl->to_dofs(nodal_force));
}

template <int dim>
Eigen::VectorXd FeBodyModel<dim>::displacement() const
{
  return impl->model.body().to_nodal(impl->model.displacement());
}

template <int dim>
Eigen::VectorXd FeBodyModel<dim>::velocity() const
{
  return impl->model.body().to_nodal(impl->model.velocity());
}

template <int dim>
double FeBodyModel<dim>::kinetic_energy() const
{
  return impl->model.kinetic_energy();
}

template <int dim>
double FeBodyModel<dim>::strain_energy() const
{
  return impl->model.strain_energy(impl->model.displacement());
}

template <int dim>
Eigen::VectorXd FeBodyModel<dim>::solve_static(const Eigen::VectorXd& nodal_force,
                                               unsigned int increments)
{
  return impl->model.body().to_nodal(
      impl->model.solve_static(impl->to_dofs(nodal_force), increments));
}

// The state as DoF vectors in the DoF numbering, which a model rebuilt from the same
// mesh and settings repeats: u, v, a, then the load of the last step.
template <int dim>
std::vector<double> FeBodyModel<dim>::state() const
{
  const auto& m = impl->model;
  std::vector<double> s;
  for (const auto* v : {&m.displacement(), &m.velocity(), &m.acceleration(), &m.last_force()})
  {
    const Vector<double> all(*v);
    s.insert(s.end(), all.begin(), all.end());
  }
  return s;
}

template <int dim>
void FeBodyModel<dim>::restore(const std::vector<double>& state)
{
  const auto& b = impl->model.body();
  const std::size_t n = b.dof_handler.n_dofs();
  if (state.size() != 4 * n)
    throw std::invalid_argument("FeBodyModel::restore: state of the wrong size");
  std::vector<PETScWrappers::MPI::Vector> v(4, b.new_vector());
  for (int k = 0; k < 4; ++k)
  {
    for (const auto dof : b.locally_owned_dofs)
      v[k](dof) = state[k * n + dof];
    v[k].compress(VectorOperation::insert);
  }
  impl->model.set_state(impl->options, v[0], v[1], v[2], v[3]);
}

template class FeBodyModel<2>;
template class FeBodyModel<3>;
} // namespace chipflex::fem
