#include "truss_beam.h"

#include <Eigen/Eigenvalues>
#include <vector>

namespace chipflex::mbs::test
{
namespace
{
Eigen::MatrixXd outer_product(const Eigen::MatrixXd& ms, const Eigen::MatrixXd& a,
                              const Eigen::MatrixXd& b)
{
  return a.transpose() * ms * b; // C(a, b) = sum_ij Ms_ij a_i b_j^T, rows of a, b = nodes
}

/// Mode k as an n x dim matrix (row = node).
Eigen::MatrixXd mode_rows(const Eigen::MatrixXd& psi, int k, int dim)
{
  const int n = static_cast<int>(psi.rows()) / dim;
  Eigen::MatrixXd r(n, dim);
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < dim; ++c)
      r(i, c) = psi(i * dim + c, k);
  return r;
}
} // namespace

TrussBeam make_truss_beam(const TrussBeamSpec& spec)
{
  const int dim = spec.dim;
  const int nx = spec.n_cells + 1;
  const int layers = dim == 2 ? 2 : 4; // nodes per cross-section
  const int n = nx * layers;
  Eigen::MatrixXd x(n, dim);
  for (int i = 0; i < nx; ++i)
    for (int c = 0; c < layers; ++c)
    {
      const int id = i * layers + c;
      x(id, 0) = spec.length * i / spec.n_cells;
      x(id, 1) = (c % 2 == 0 ? -0.5 : 0.5) * spec.height;
      if (dim == 3)
        x(id, 2) = (c < 2 ? -0.5 : 0.5) * spec.depth;
    }
  // bars: all pairs of nodes within one cell (both cross-sections): edges and diagonals
  std::vector<std::pair<int, int>> bars;
  for (int i = 0; i < nx; ++i)
    for (int a = 0; a < layers; ++a)
    {
      for (int b = a + 1; b < layers; ++b)
        bars.push_back({i * layers + a, i * layers + b});
      if (i + 1 < nx)
        for (int b = 0; b < layers; ++b)
          bars.push_back({i * layers + a, (i + 1) * layers + b});
    }
  double total_length = 0;
  for (auto [a, b] : bars)
    total_length += (x.row(a) - x.row(b)).norm();
  const double volume = spec.length * spec.height * (dim == 3 ? spec.depth : 1.0);
  const double line_density = spec.density * volume / total_length;

  Eigen::MatrixXd ms = Eigen::MatrixXd::Zero(n, n);
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(dim * n, dim * n);
  for (auto [a, b] : bars)
  {
    const Eigen::VectorXd d = (x.row(b) - x.row(a)).transpose();
    const double le = d.norm();
    const double me = line_density * le;
    ms(a, a) += me / 3;
    ms(b, b) += me / 3;
    ms(a, b) += me / 6;
    ms(b, a) += me / 6;
    const Eigen::MatrixXd ke = spec.bar_stiffness / le * (d / le) * (d / le).transpose();
    k.block(dim * a, dim * a, dim, dim) += ke;
    k.block(dim * b, dim * b, dim, dim) += ke;
    k.block(dim * a, dim * b, dim, dim) -= ke;
    k.block(dim * b, dim * a, dim, dim) -= ke;
  }
  Eigen::MatrixXd m_full = Eigen::MatrixXd::Zero(dim * n, dim * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int c = 0; c < dim; ++c)
        m_full(dim * i + c, dim * j + c) = ms(i, j);

  // free degrees of freedom: all, or all but the x = 0 cross-section
  std::vector<int> free;
  for (int i = spec.clamped ? layers : 0; i < n; ++i)
    for (int c = 0; c < dim; ++c)
      free.push_back(dim * i + c);
  const int nf = static_cast<int>(free.size());
  Eigen::MatrixXd kf(nf, nf), mf(nf, nf);
  for (int r = 0; r < nf; ++r)
    for (int c = 0; c < nf; ++c)
    {
      kf(r, c) = k(free[r], free[c]);
      mf(r, c) = m_full(free[r], free[c]);
    }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(kf, mf);
  const int n_rigid = spec.clamped ? 0 : (dim == 2 ? 3 : 6);
  const int available = nf - n_rigid;
  const int m = spec.n_modes < 0 ? available : std::min(spec.n_modes, available);
  Eigen::MatrixXd psi = Eigen::MatrixXd::Zero(dim * n, m);
  for (int j = 0; j < m; ++j)
    for (int r = 0; r < nf; ++r)
      psi(free[r], j) = eig.eigenvectors()(r, n_rigid + j);

  ReducedBodyData d;
  d.dim = dim;
  d.youngs_modulus = 0;
  d.density = spec.density;
  d.model = dim == 2 ? "truss_2d" : "truss_3d";
  d.mesh_file = "truss beam (test)";
  d.clamp_set = spec.clamped ? "clamp" : "";
  d.nodes = x;
  for (int i = 0; i < n; ++i)
    d.skin_nodes.push_back(i);
  std::vector<int> clamp, tip;
  for (int c = 0; c < layers; ++c)
  {
    clamp.push_back(c);
    tip.push_back((nx - 1) * layers + c);
  }
  d.node_sets["clamp"] = clamp;
  d.node_sets["tip"] = tip;
  d.node_sets["skin"] = d.skin_nodes;
  if (dim == 2)
  {
    // outline counter-clockwise: bottom row (c = 0) left to right, top row back
    std::vector<int> ring;
    for (int i = 0; i < nx; ++i)
      ring.push_back(i * 2);
    for (int i = nx - 1; i >= 0; --i)
      ring.push_back(i * 2 + 1);
    d.skin_faces.resize(static_cast<int>(ring.size()), 2);
    for (std::size_t s = 0; s < ring.size(); ++s)
    {
      d.skin_faces(static_cast<int>(s), 0) = ring[s];
      d.skin_faces(static_cast<int>(s), 1) = ring[(s + 1) % ring.size()];
    }
  }
  else
  {
    // the four long sides as triangle strips, oriented away from the axis
    std::vector<std::array<int, 3>> tris;
    const int sides[4][2] = {{0, 1}, {1, 3}, {3, 2}, {2, 0}};
    for (auto [p, q] : sides)
      for (int i = 0; i + 1 < nx; ++i)
      {
        const int a = i * 4 + p, b = (i + 1) * 4 + p, c = (i + 1) * 4 + q, e = i * 4 + q;
        for (std::array<int, 3> t : {std::array<int, 3>{a, b, c}, std::array<int, 3>{a, c, e}})
        {
          const Eigen::Vector3d pa = x.row(t[0]).transpose(), pb = x.row(t[1]).transpose(),
                                pc = x.row(t[2]).transpose();
          Eigen::Vector3d out = (pa + pb + pc) / 3;
          out.x() = 0; // outward = away from the x axis
          if ((pb - pa).cross(pc - pa).dot(out) < 0)
            std::swap(t[1], t[2]);
          tris.push_back(t);
        }
      }
    d.skin_faces.resize(static_cast<int>(tris.size()), 3);
    for (std::size_t t = 0; t < tris.size(); ++t)
      for (int c = 0; c < 3; ++c)
        d.skin_faces(static_cast<int>(t), c) = tris[t][c];
  }
  d.psi = psi;
  d.mode_kinds.assign(m, "normal");
  d.mass_matrix = psi.transpose() * m_full * psi;
  d.stiffness_matrix = psi.transpose() * k * psi;
  d.frequencies_hz.resize(m);
  for (int j = 0; j < m; ++j)
    d.frequencies_hz(j) = std::sqrt(std::max(0.0, d.stiffness_matrix(j, j))) / (2 * M_PI);

  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(n);
  d.mass = ones.dot(ms * ones);
  d.center_of_mass = (x.transpose() * ms * ones) / d.mass;
  d.c_xx = outer_product(ms, x, x);
  const Eigen::MatrixXd s_c = d.c_xx - d.mass * d.center_of_mass * d.center_of_mass.transpose();
  d.inertia_tensor.setZero();
  if (dim == 2)
  {
    d.inertia_tensor(0, 0) = s_c(1, 1);
    d.inertia_tensor(1, 1) = s_c(0, 0);
    d.inertia_tensor(0, 1) = d.inertia_tensor(1, 0) = -s_c(0, 1);
    d.inertia_tensor(2, 2) = s_c.trace();
  }
  else
    d.inertia_tensor = s_c.trace() * Eigen::Matrix3d::Identity() - s_c;
  d.translation_coupling.resize(dim, m);
  std::vector<Eigen::MatrixXd> rows(m);
  for (int j = 0; j < m; ++j)
  {
    rows[j] = mode_rows(psi, j, dim);
    d.translation_coupling.col(j) = rows[j].transpose() * ms * ones;
    d.c_x_psi.push_back(outer_product(ms, x, rows[j]));
  }
  for (int a = 0; a < m; ++a)
    for (int b = 0; b < m; ++b)
      d.c_psi_psi.push_back(outer_product(ms, rows[a], rows[b]));
  return {d, ms, k};
}
} // namespace chipflex::mbs::test
