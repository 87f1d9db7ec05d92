// reduce_body(): the `chipflex reduce` pipeline, dispatched on the mesh dimension.

#include "common/input_error.h"
#include "common/wall_clock.h"
#include "fem/elastic_body.h"
#include "fem/gmsh_reader.h"
#include "fem/inertia_invariants.h"
#include "fem/matrix_export.h"
#include "fem/modal_reduction.h"
#include "fem/reduce.h"
#include "fem/svk_reduced_forces.h"

#include <chrono>
#include <stdexcept>

namespace chipflex::fem
{
namespace
{
using clock = WallClock;

template <int dim>
ReducedBodyData reduce(const GmshMeshData& mesh, const ReductionSettings& settings,
                       ReductionTimings& timings)
{
  std::vector<LoadCase> cases;
  for (const auto& text : settings.static_modes)
  {
    cases.push_back(LoadCase::parse(text, dim, "--static-modes"));
    mesh.require_group(cases.back().group, "--static-modes " + text);
  }
  auto t0 = clock::now();
  ElasticBody<dim> body(mesh, settings.material, settings.degree, settings.clamp_group,
                        MPI_COMM_WORLD);
  body.setup_system();
  timings.setup = seconds_since(t0);
  timings.n_dofs = body.dof_handler.n_dofs();
  timings.n_cells = body.triangulation.n_active_cells();
  t0 = clock::now();
  body.assemble_system();
  timings.assembly = seconds_since(t0);
  if (!settings.export_directory.empty())
    export_matrices(body, settings.export_directory,
                    parse_matrix_export_format(settings.export_format, "--export-matrices-format"));

  unsigned int derivative_modes = 0;
  if (settings.nonlinear)
    derivative_modes =
        settings.derivative_modes ? settings.derivative_modes : std::min(settings.n_modes, 5u);
  ModalReduction<dim> reduction(body, settings.n_modes, cases, derivative_modes);
  reduction.run(timings);

  t0 = clock::now();
  ReducedBodyData data;
  data.dim = dim;
  data.youngs_modulus = settings.material.youngs_modulus;
  data.poisson_ratio = settings.material.poisson_ratio;
  data.density = settings.material.density;
  data.model = settings.material.model_name(dim);
  data.mesh_file = settings.mesh_file;
  data.mesh_hash = file_hash(settings.mesh_file);
  data.element_degree = settings.degree;
  data.clamp_set = settings.clamp_group;
  data.tool_version = "chipflex 0.1.0";

  data.nodes.resize(body.n_nodes(), dim);
  for (unsigned int i = 0; i < body.n_nodes(); ++i)
    for (int d = 0; d < dim; ++d)
      data.nodes(i, d) = body.node_coordinates[i][d];
  data.skin_nodes = body.skin_nodes;
  data.skin_faces.resize(body.skin_faces.size(), dim);
  for (std::size_t f = 0; f < body.skin_faces.size(); ++f)
    for (int d = 0; d < dim; ++d)
      data.skin_faces(f, d) = body.skin_faces[f][d];
  data.node_sets = body.node_sets;

  data.psi = reduction.basis;
  data.mode_kinds = reduction.kinds;
  data.stiffness_matrix = reduction.reduced_stiffness;
  // K_red is diagonal (the static modes rotated to Ritz vectors, fem/modal_reduction.h), so
  // its diagonal holds the reduced model's own frequencies squared.
  data.frequencies_hz.resize(data.psi.cols());
  for (int k = 0; k < data.psi.cols(); ++k)
    data.frequencies_hz[k] = std::sqrt(std::max(0., data.stiffness_matrix(k, k))) / (2 * M_PI);
  compute_inertia_invariants(body.scalar_mass_matrix, data);
  if (settings.nonlinear)
  {
    const auto t1 = clock::now();
    SvkPolynomial svk = svk_polynomial(body, data.psi);
    // The polynomial's linear part comes from the same quadrature as K: it must be Psi^T K Psi.
    const double scale = data.stiffness_matrix.cwiseAbs().maxCoeff();
    if ((svk.linear - data.stiffness_matrix).cwiseAbs().maxCoeff() > 1e-8 * scale)
      throw std::logic_error("reduce --nonlinear: the St Venant-Kirchhoff linear part differs "
                             "from Psi^T K Psi");
    data.quadratic_stiffness = std::move(svk.quadratic);
    data.cubic_stiffness = std::move(svk.cubic);
    data.n_modal_derivatives = reduction.n_derivatives;
    timings.nonlinear = seconds_since(t1);
  }

  if (!settings.vtu_file.empty())
  {
    std::vector<std::string> names;
    for (int k = 0; k < data.psi.cols(); ++k)
      names.push_back("mode_" + std::to_string(k + 1));
    body.output_modes(settings.vtu_file, data.psi, names);
  }
  timings.post_processing = seconds_since(t0);
  return data;
}
} // namespace

ReducedBodyData reduce_body(const ReductionSettings& settings, ReductionTimings* timings)
{
  settings.material.check();
  if (settings.degree != 1 && settings.degree != 2)
    throw InputError("--degree", "must be 1 or 2");
  ReductionTimings local;
  ReductionTimings& t = timings ? *timings : local;
  const auto t0 = clock::now();
  GmshMeshData mesh = read_gmsh_mesh(settings.mesh_file);
  if (settings.straight_sided)
  {
    mesh.order = 1;
    mesh.complete_second_order = true;
    mesh.midpoint_nodes.clear();
  }
  t.mesh_reading = seconds_since(t0);
  if (mesh.dim == 2)
    return reduce<2>(mesh, settings, t);
  return reduce<3>(mesh, settings, t);
}
} // namespace chipflex::fem
