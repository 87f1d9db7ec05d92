#pragma once
// `chipflex compare`: a clamped reduced body against the full FE model it came from. It sits
// above both layers it compares: the full side is fem/ (fem/full_response.h), the reduced
// side runs through the simulation's own body model in mbs/ (mbs::FloatingFrameBody). fem/
// and mbs/ never see each other; only apps/ and tests use this library. Collective over
// MPI_COMM_WORLD (call after MPI/PETSc initialisation); every process gets the same result.

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace chipflex::compare
{
struct CompareSettings
{
  std::string mesh_file, body_file;
  std::string load;     ///< force:GROUP:fx,fy[,fz]
  double duration = 0;  ///< s; 0: five periods of the first mode
  double time_step = 0; ///< s; 0: 1/40 of the first period
  /// The full side geometrically nonlinear (total Lagrangian, the load a dead load), the
  /// reduced side's static response its own equilibrium under the body file's internal
  /// force (whatever the body file holds), not the linear K_red solve.
  bool nonlinear = false;
  std::string material_model = "svk"; ///< nonlinear: svk or neo-hooke
  unsigned int load_increments = 10;  ///< nonlinear statics
};

struct CompareResult
{
  std::string group;
  Eigen::VectorXd static_full, static_reduced; ///< centroid displacement of the group
  double static_rel_error = 0;
  std::vector<double> time;
  Eigen::MatrixXd transient_full, transient_reduced; ///< (steps + 1) x dim
  double transient_rel_error = 0;                    ///< max_t |u_r - u_f| / max_t |u_f|
  double full_seconds = 0, reduced_seconds = 0;
  std::string reduced_integrator; ///< which reduced model ran
  /// The transients' generalised-alpha rho_infinity on the full and the reduced side: 1
  /// (the trapezoidal rule) unless a nonlinear transient failed with it (then 0.9, 0.7, 0.5).
  double rho_infinity = 1, reduced_rho_infinity = 1;
};

/// Static and transient (step load, Newmark average acceleration) response of the full FE
/// model against the reduced body. The body must be clamped and made from this mesh.
/// Nonlinear: the reduced static response is the reduced body's own equilibrium (Newton in
/// load increments on its internal force), which for a linear body file is K_red^-1 Psi^T f.
CompareResult compare_with_full(const CompareSettings& settings);
} // namespace chipflex::compare
