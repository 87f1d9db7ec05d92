#include "fem/inertia_invariants.h"

namespace chipflex::fem
{
void compute_inertia_invariants(const Eigen::SparseMatrix<double>& ms, ReducedBodyData& body)
{
  const int dim = body.dim, n = body.n_nodes(), m = body.n_modes();
  const Eigen::MatrixXd& x = body.nodes; // n x dim
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(n);
  const Eigen::VectorXd ms_ones = ms * ones;

  body.mass = ones.dot(ms_ones);
  body.center_of_mass = x.transpose() * ms_ones / body.mass;
  const Eigen::MatrixXd ms_x = ms * x;
  body.c_xx = x.transpose() * ms_x;
  body.c_xx = (0.5 * (body.c_xx + body.c_xx.transpose())).eval(); // symmetric by definition

  // Second moments about the centre of mass, J = C(x, x) - m c c^T, embedded in 3D
  // (z = 0 in 2D); the inertia tensor is I = trace(J) 1 - J.
  Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
  j.topLeftCorner(dim, dim) =
      body.c_xx - body.mass * body.center_of_mass * body.center_of_mass.transpose();
  body.inertia_tensor = j.trace() * Eigen::Matrix3d::Identity() - j;

  // Mode k as an n x dim field: row i = displacement of node i (psi row = node*dim + c).
  auto field = [&](int k)
  {
    return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        body.psi.col(k).data(), n, dim);
  };
  std::vector<Eigen::MatrixXd> fields(m), ms_fields(m);
  for (int k = 0; k < m; ++k)
  {
    fields[k] = field(k);
    ms_fields[k] = ms * fields[k];
  }
  body.translation_coupling.resize(dim, m);
  body.c_x_psi.assign(m, Eigen::MatrixXd());
  body.c_psi_psi.assign(std::size_t(m) * m, Eigen::MatrixXd());
  body.mass_matrix.resize(m, m);
  for (int k = 0; k < m; ++k)
  {
    body.translation_coupling.col(k) = ms_fields[k].transpose() * ones;
    body.c_x_psi[k] = x.transpose() * ms_fields[k];
    // C(psi_l, psi_k) = C(psi_k, psi_l)^T exactly (Ms is symmetric).
    for (int l = k; l < m; ++l)
    {
      Eigen::MatrixXd c = fields[k].transpose() * ms_fields[l];
      if (l == k)
        c = (0.5 * (c + c.transpose())).eval();
      body.c_psi_psi[k * m + l] = c;
      body.c_psi_psi[l * m + k] = c.transpose();
      body.mass_matrix(k, l) = body.mass_matrix(l, k) = c.trace();
    }
  }
}
} // namespace chipflex::fem
