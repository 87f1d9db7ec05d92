// compare_body_files A.h5 B.h5: exit 0 when two body files hold the same body (every
// dataset within a relative 1e-8 of its norm; strings and ids equal), else print the
// first difference and exit 1. Used by the MPI-equals-serial test.
#include "common/input_error.h"
#include "common/reduced_body_file.h"

#include <iostream>

using chipflex::ReducedBodyData;

namespace
{
/// Relative 1e-8, with an absolute floor for quantities that vanish by construction
/// (a free body's translation coupling is zero up to round-off).
bool close(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const char* what,
           double floor = 1e-300)
{
  if (a.rows() != b.rows() || a.cols() != b.cols() ||
      (a - b).norm() > 1e-8 * std::max(floor, a.norm()))
  {
    std::cerr << what << " differs: |a - b| = "
              << (a.rows() == b.rows() && a.cols() == b.cols() ? (a - b).norm() : -1.0)
              << ", |a| = " << a.norm() << "\n";
    return false;
  }
  return true;
}
} // namespace

int main(int argc, char** argv)
{
  if (argc != 3)
  {
    std::cerr << "usage: compare_body_files A.h5 B.h5\n";
    return 2;
  }
  try
  {
    const ReducedBodyData a = chipflex::read_reduced_body(argv[1]),
                          b = chipflex::read_reduced_body(argv[2]);
    bool same = a.dim == b.dim && a.mode_kinds == b.mode_kinds && a.skin_nodes == b.skin_nodes &&
                a.node_sets == b.node_sets && a.skin_faces == b.skin_faces &&
                a.clamp_set == b.clamp_set;
    if (!same)
      std::cerr << "dimension, mode kinds, skin or node sets differ\n";
    same = same && close(a.nodes, b.nodes, "nodes") && close(a.psi, b.psi, "psi") &&
           close(a.frequencies_hz, b.frequencies_hz, "frequencies") &&
           close(a.mass_matrix, b.mass_matrix, "reduced mass") &&
           close(a.stiffness_matrix, b.stiffness_matrix, "reduced stiffness") &&
           close(a.c_xx, b.c_xx, "c_xx") && close(a.inertia_tensor, b.inertia_tensor, "inertia") &&
           close(a.translation_coupling, b.translation_coupling, "translation coupling",
                 1e-6 * std::sqrt(a.mass));
    for (std::size_t k = 0; same && k < a.c_psi_psi.size(); ++k)
      same = close(a.c_psi_psi[k], b.c_psi_psi[k], "c_psi_psi", 1.0); // traces: delta_kl
    for (std::size_t k = 0; same && k < a.c_x_psi.size(); ++k)
      same = close(a.c_x_psi[k], b.c_x_psi[k], "c_x_psi",
                   std::sqrt(a.mass) * a.nodes.cwiseAbs().maxCoeff());
    std::cout << (same ? "same body\n" : "bodies differ\n");
    return same ? 0 : 1;
  }
  catch (const std::exception& e)
  {
    std::cerr << e.what() << "\n";
    return 2;
  }
}
