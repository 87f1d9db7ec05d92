#pragma once
// The full FE model's response to one load case, the reference that `chipflex compare`
// measures a reduced body against (compare/compare_with_full.h): the static solution and the
// step-load transient (Newmark average acceleration, the matrix factorised once and reused
// every step), both observed at the centroid of the loaded group's nodes; or, with
// `nonlinear`, the same from the geometrically nonlinear model under the load as a dead load. No
// deal.II in this header; collective over MPI_COMM_WORLD like fem/reduce.h.

#include "common/reduced_body_file.h"
#include "fem/hyperelastic_model.h"

#include <Eigen/Dense>
#include <string>

namespace chipflex::fem
{
struct FullResponseSettings
{
  std::string mesh_file; ///< the mesh the body was reduced from
  std::string body_file; ///< the body file's path, for error messages
  std::string load;      ///< force:GROUP:fx,fy[,fz]
  double time_step = 0;  ///< s, > 0
  int n_steps = 0;       ///< transient steps after t = 0
  /// The geometrically nonlinear model (fem/nonlinear_elastic_body.h) instead of the
  /// linear one: Newton statics in `load_increments` increments, and the step-load
  /// transient by the trapezoidal rule with Newton on every step.
  bool nonlinear = false;
  HyperelasticModel material_model = HyperelasticModel::st_venant_kirchhoff;
  unsigned int load_increments = 10;
};

struct FullResponse
{
  std::string group;               ///< the loaded node set
  Eigen::VectorXd nodal_force;     ///< consistent nodal forces of the load, row node*dim + d
  Eigen::VectorXd static_centroid; ///< mean displacement of the group's nodes, K u = f
  Eigen::MatrixXd transient;       ///< (n_steps + 1) x dim: the same mean under the step load
  double seconds = 0;              ///< assembly and both solutions
  /// The transient's generalised-alpha rho_infinity: 1 (the trapezoidal rule), lower only
  /// when the nonlinear model's trapezoidal transient failed (fem/full_response.cc).
  double rho_infinity = 1;
};

/// The full model of `body` (its material, element degree and clamp) on the mesh it was
/// reduced from, under settings.load. Throws InputError if the mesh is not the body's (hash,
/// dimension, nodes) or the load is bad.
FullResponse full_response(const ReducedBodyData& body, const FullResponseSettings& settings);
} // namespace chipflex::fem
