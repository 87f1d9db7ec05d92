// The assembled operators and the skin: K and M symmetric, M without the zero
// cross-component entries; rigid motion costs no strain
// energy (K r = 0 for translations and rotations, the defining property of an elasticity
// stiffness); the skin is closed and faces outward (divergence theorem: the sum of
// x . n dA / dim over the skin pieces is the body's volume, or area in 2D).
#include "fem/elastic_body.h"
#include "fem_test_support.h"

#include <catch2/catch.hpp>

using namespace chipflex;
using namespace chipflex::fem;
using namespace chipflex::fem::testing;

namespace
{
template <int dim>
void check_operators(const std::string& mesh_file, unsigned int degree)
{
  const GmshMeshData mesh = read_gmsh_mesh(mesh_file);
  ElasticBody<dim> body(mesh, Material{1.2e7, 0.4, 1100, false}, degree, "", MPI_COMM_WORLD);
  body.setup_system();
  body.assemble_system();
  PetscBool symmetric;
  const double scale_k = body.stiffness_matrix.linfty_norm();
  MatIsSymmetric(body.stiffness_matrix, 1e-13 * scale_k, &symmetric);
  CHECK(symmetric == PETSC_TRUE);
  MatIsSymmetric(body.mass_matrix, 1e-13 * body.mass_matrix.linfty_norm(), &symmetric);
  CHECK(symmetric == PETSC_TRUE);
  CHECK((body.scalar_mass_matrix - Eigen::SparseMatrix<double>(body.scalar_mass_matrix.transpose()))
            .norm() < 1e-14 * body.scalar_mass_matrix.norm());
  // M = Ms (x) I keeps exactly the equal-component third (half in 2D) of K's entries, and
  // a node's DoFs are one aligned block, which the direct solver's analysis relies on.
  MatInfo info_k, info_m;
  MatGetInfo(body.stiffness_matrix, MAT_GLOBAL_SUM, &info_k);
  MatGetInfo(body.mass_matrix, MAT_GLOBAL_SUM, &info_m);
  CHECK(info_m.nz_used * dim == info_k.nz_used);
  CHECK(body.node_block_size == dim);

  // Rigid modes: translations e_d and a rotation about z (x, y) -> (-y, x).
  const int n = body.n_nodes();
  auto v = body.new_vector(), kv = body.new_vector();
  for (int mode = 0; mode <= dim; ++mode)
  {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(dim * n);
    for (int i = 0; i < n; ++i)
      if (mode < dim)
        r[i * dim + mode] = 1;
      else
      {
        r[i * dim + 0] = -body.node_coordinates[i][1];
        r[i * dim + 1] = body.node_coordinates[i][0];
      }
    body.from_nodal(r, v);
    body.stiffness_matrix.vmult(kv, v);
    INFO("rigid mode " << mode);
    CHECK(kv.l2_norm() < 1e-10 * scale_k * v.l2_norm());
  }
}

double enclosed_measure(const ReducedBodyData& body)
{
  double sum = 0;
  for (int f = 0; f < body.skin_faces.rows(); ++f)
  {
    if (body.dim == 2)
    {
      const Eigen::Vector2d a = body.nodes.row(body.skin_faces(f, 0)).transpose(),
                            b = body.nodes.row(body.skin_faces(f, 1)).transpose();
      const Eigen::Vector2d normal_length(b[1] - a[1], -(b[0] - a[0])); // n |ab|
      sum += 0.5 * (0.5 * (a + b)).dot(normal_length);
    }
    else
    {
      const Eigen::Vector3d a = body.nodes.row(body.skin_faces(f, 0)).transpose(),
                            b = body.nodes.row(body.skin_faces(f, 1)).transpose(),
                            c = body.nodes.row(body.skin_faces(f, 2)).transpose();
      sum += ((a + b + c) / 3).dot(0.5 * (b - a).cross(c - a)) / 3;
    }
  }
  return sum;
}
} // namespace

TEST_CASE("stiffness and mass symmetric, rigid motion strain-free", "[fem]")
{
  check_operators<2>(gate_mesh(0.0025), 2);
  check_operators<2>(gate_mesh(0.0025, true), 2);
  check_operators<3>(strip_mesh(0.02, 0.006, 0.004, 0.002), 2);
  check_operators<3>(strip_mesh(0.02, 0.006, 0.004, 0.002, true), 2);
  check_operators<3>(strip_mesh(0.02, 0.006, 0.004, 0.002, true), 1);
}

TEST_CASE("skin: closed, outward, through every boundary node", "[fem]")
{
  struct Case
  {
    std::string mesh;
    double measure;
  };
  const std::vector<Case> cases = {
      {gate_mesh(0.0025), 0.005 * 0.079},
      {gate_mesh(0.0025, true), 0.005 * 0.079},
      {strip_mesh(0.02, 0.006, 0.004, 0.002), 0.02 * 0.006 * 0.004},
      {strip_mesh(0.02, 0.006, 0.004, 0.002, true), 0.02 * 0.006 * 0.004}};
  for (const auto& c : cases)
    for (const unsigned int degree : {1u, 2u})
    {
      ReductionSettings s;
      s.material = {1.2e7, 0.4, 1100, false}; // the gate's rubber
      s.mesh_file = c.mesh;
      s.degree = degree;
      s.n_modes = 1;
      s.clamp_group = "clamp";
      const auto body = reduce_body(s);
      INFO(c.mesh << " degree " << degree);
      CHECK(enclosed_measure(body) == Approx(c.measure).epsilon(1e-12));
      // Every skin node is used by a face, and the "skin" group's nodes are the skin.
      std::set<int> used(body.skin_faces.data(), body.skin_faces.data() + body.skin_faces.size());
      CHECK(std::vector<int>(used.begin(), used.end()) == body.skin_nodes);
      CHECK(body.node_sets.at("skin") == body.skin_nodes);
    }
}
