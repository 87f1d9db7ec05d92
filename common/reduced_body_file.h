#pragma once
// The reduced floating-frame body file, format version 2 (version 1 still read): the only contract
// between fem/ (which writes it, `chipflex reduce`) and mbs/ (which reads it). Both sides use this
// one reader/writer so that they agree byte for byte. Schema and the meaning of every quantity:
// docs/body_file_format.md.
//
// Notation (docs/body_file_format.md): n nodes with reference positions x_i, the
// consistent mass matrix of the vector problem M = Ms (x) I_dim with the scalar mass
// matrix Ms, mass-orthonormal modes Psi = [psi_1 .. psi_m] (psi_k holds one vector per
// node). All inertia quantities are "mass-weighted outer products"
//     C(a, b) = sum_ij Ms_ij a_i b_j^T          (a dim x dim matrix)
// from which every term of the floating-frame equations of motion follows, in 2D and
// 3D alike (cross products and their 2D analogues are linear in these entries).

#include <Eigen/Dense>
#include <map>
#include <string>
#include <vector>

namespace chipflex
{
struct ReducedBodyData
{
  /// Written: 2. Read: 1 (linear bodies) and 2 (optionally with /nonlinear).
  static constexpr int format_version = 2;
  /// the version of the file read (read_reduced_body); written files are format_version
  int file_version = format_version;

  // ---- /meta
  int dim = 0;
  double youngs_modulus = 0; ///< Pa
  double poisson_ratio = 0;  ///< -
  double density = 0;        ///< kg/m^3
  std::string model;         ///< "plane_strain", "plane_stress" or "solid_3d"
  std::string mesh_file;     ///< as given to `chipflex reduce`
  std::string mesh_hash;     ///< FNV-1a 64-bit hash of the mesh file bytes, hex
  int element_degree = 0;    ///< 1 or 2
  std::string clamp_set;     ///< node set fixed to the frame; empty = free-free
  std::string tool_version;  ///< e.g. "chipflex 0.1.0"

  // ---- /mesh
  Eigen::MatrixXd nodes;       ///< n x dim reference coordinates of all FE nodes
  std::vector<int> skin_nodes; ///< node ids on the boundary, ascending
  Eigen::MatrixXi skin_faces;  ///< n_faces x dim node ids: segments (2D) / triangles (3D),
                               ///< linear pieces, ordered so the normal points outward
  std::map<std::string, std::vector<int>> node_sets; ///< physical groups -> node ids

  // ---- /modes
  Eigen::MatrixXd psi;                 ///< (dim n) x m, row = node * dim + component
  Eigen::VectorXd frequencies_hz;      ///< per column: sqrt(psi^T K psi) / 2 pi
  std::vector<std::string> mode_kinds; ///< "normal" or "static:<load case>"

  // ---- /reduced
  Eigen::MatrixXd mass_matrix;      ///< Psi^T M Psi (identity up to round-off)
  Eigen::MatrixXd stiffness_matrix; ///< Psi^T K Psi

  // ---- /inertia (all from the consistent mass matrix)
  double mass = 0;                        ///< kg (2D: per metre of depth)
  Eigen::VectorXd center_of_mass;         ///< dim
  Eigen::Matrix3d inertia_tensor;         ///< about the centre of mass; 2D: z is out of plane
  Eigen::MatrixXd c_xx;                   ///< C(x, x), dim x dim
  Eigen::MatrixXd translation_coupling;   ///< dim x m: column k = sum_ij Ms_ij psi_k,j
                                          ///< (= Phi_t^T M Psi)
  std::vector<Eigen::MatrixXd> c_x_psi;   ///< m entries: C(x, psi_k)
  std::vector<Eigen::MatrixXd> c_psi_psi; ///< m*m entries, index k*m+l: C(psi_k, psi_l)

  // ---- /nonlinear (version 2, optional): the reduced St Venant-Kirchhoff internal force
  // f(q) = K q + Q:(q q) + C:(q q q) (common/polynomial_stiffness.h), K = stiffness_matrix
  std::vector<double> quadratic_stiffness; ///< Q, sorted i <= j <= k; empty: linear body
  std::vector<double> cubic_stiffness;     ///< C, sorted i <= j <= k <= l
  int n_modal_derivatives = 0;             ///< basis columns that are modal derivatives

  bool nonlinear() const { return !quadratic_stiffness.empty(); }
  int n_nodes() const { return static_cast<int>(nodes.rows()); }
  int n_modes() const { return static_cast<int>(psi.cols()); }
};

/// Writes atomically (temporary file, then rename).
void write_reduced_body(const std::string& path, const ReducedBodyData& body);

/// Reads and checks every shape against /meta; throws InputError naming the file and
/// the object at fault for a missing, truncated, foreign or inconsistent file.
ReducedBodyData read_reduced_body(const std::string& path);

/// FNV-1a 64-bit hash of a file's bytes as 16 hex digits (a cheap identity check).
std::string file_hash(const std::string& path);
} // namespace chipflex
