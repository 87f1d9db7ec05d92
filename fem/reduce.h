#pragma once
// The fem layer's entry point for apps/ and bench/ (no deal.II in this header): reduce a
// mesh to a floating-frame body. Collective over MPI_COMM_WORLD (call after MPI/PETSc
// initialisation, e.g. dealii::Utilities::MPI::MPI_InitFinalize); every process gets the
// same result. The full-FE reference for `compare` is fem/full_response.h.

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
  unsigned int degree = 2; ///< element degree on the gmsh cells, 1 or 2
  /// A second-order mesh's cells are curved (isoparametric mapping on the gmsh nodes) with
  /// degree 2; true: straight-sided through the corners, as for a linear mesh.
  bool straight_sided = false;
  std::string clamp_group;               ///< empty: free-free body
  unsigned int n_modes = 10;             ///< elastic normal modes (rigid modes never counted)
  std::vector<std::string> static_modes; ///< load cases, e.g. "pressure:skin", "force:tip:0,-1"
  /// Geometrically nonlinear body (St Venant-Kirchhoff): the basis gains the static modal
  /// derivatives of the first `derivative_modes` normal modes (all pairs), and the file the
  /// reduced internal force as a cubic polynomial (fem/svk_reduced_forces.h).
  bool nonlinear = false;
  unsigned int derivative_modes = 0; ///< 0 with nonlinear: min(n_modes, 5)
  std::string vtu_file;              ///< mode shapes for ParaView; empty: none
  std::string export_directory;      ///< M and K (docs/export_matrices.md); empty: none
  std::string export_format = "mtx"; ///< mtx: M.mtx, K.mtx, dof_nodes.csv; hdf5: matrices.h5
};

struct ReductionTimings
{
  double mesh_reading = 0, setup = 0, assembly = 0, factorisation = 0, eigen_solve = 0,
         static_modes = 0, basis = 0, post_processing = 0, nonlinear = 0;
  std::size_t n_dofs = 0, n_cells = 0;
};

/// The whole reduction: mesh -> K, M -> normal and static modes -> mass-orthonormal basis
/// -> inertia invariants. Throws InputError for bad input.
ReducedBodyData reduce_body(const ReductionSettings& settings, ReductionTimings* timings = nullptr);
} // namespace chipflex::fem
