#pragma once
// The fem layer's entry points for apps/ and bench/ (no deal.II in this header):
// reduce a mesh to a floating-frame body, and compare a body against the full FE model.
// Both are collective over MPI_COMM_WORLD (call after MPI/PETSc initialisation, e.g.
// dealii::Utilities::MPI::MPI_InitFinalize) and return the same result on every process.

#include "common/reduced_body_file.h"
#include "fem/material.h"

#include <string>
#include <vector>

namespace chipflex::fem
{
struct ReductionSettings
{
  std::string mesh_file;
  Material material;
  unsigned int degree = 2;               ///< element degree on the gmsh cells, 1 or 2
  std::string clamp_group;               ///< empty: free-free body
  unsigned int n_modes = 10;             ///< elastic normal modes (rigid modes never counted)
  std::vector<std::string> static_modes; ///< load cases, e.g. "pressure:skin", "force:tip:0,-1"
  std::string vtu_file;                  ///< mode shapes for ParaView; empty: none
  std::string export_directory;          ///< M.mtx, K.mtx, dof_nodes.csv; empty: none
};

struct ReductionTimings
{
  double mesh_reading = 0, setup = 0, assembly = 0, factorisation = 0, eigen_solve = 0,
         static_modes = 0, basis = 0, post_processing = 0;
  std::size_t n_dofs = 0, n_cells = 0;
};

/// The whole reduction: mesh -> K, M -> normal and static modes -> mass-orthonormal basis
/// -> inertia invariants. Throws InputError for bad input.
ReducedBodyData reduce_body(const ReductionSettings& settings, ReductionTimings* timings = nullptr);

struct CompareSettings
{
  std::string mesh_file, body_file;
  std::string load;     ///< force:GROUP:fx,fy[,fz]
  double duration = 0;  ///< s; 0: five periods of the first mode
  double time_step = 0; ///< s; 0: 1/40 of the first period
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
};

/// Static and transient (step load, Newmark average acceleration) response of the full FE
/// model against the reduced body. The body must be clamped and made from this mesh.
CompareResult compare_with_full(const CompareSettings& settings);
} // namespace chipflex::fem
