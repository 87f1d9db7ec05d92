#include "common/sid_writer.h"

#include "common/atomic_output.h"
#include "common/input_error.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace chipflex
{
namespace
{
using Matrix3 = Eigen::Matrix3d;
using Vector3 = Eigen::Vector3d;

/// A dim x dim matrix embedded in 3 x 3 (2D: z row and column zero).
Matrix3 embed(const Eigen::MatrixXd& a)
{
  Matrix3 m = Matrix3::Zero();
  m.topLeftCorner(a.rows(), a.cols()) = a;
  return m;
}

/// Axial vector of the antisymmetric part: (C_yz - C_zy, C_zx - C_xz, C_xy - C_yx), so
/// that sum_ij Ms_ij a_i x b_j = axial(C(a, b)).
Vector3 axial(const Matrix3& c)
{
  return {c(1, 2) - c(2, 1), c(2, 0) - c(0, 2), c(0, 1) - c(1, 0)};
}

/// tr(C) 1 - C: the inertia-tensor form of a second moment.
Matrix3 inertia_form(const Matrix3& c)
{
  return c.trace() * Matrix3::Identity() - c;
}

/// The six centrifugal coefficients of the modal force for G = C(u, psi_k): the term
/// sum_ij Ms_ij psi_k,i . (w~ w~ u_j) = -w^T B w, B = tr(G) 1 - sym(G), as a row over
/// (wx^2, wy^2, wz^2, wx wy, wy wz, wz wx).
Eigen::Matrix<double, 1, 6> centrifugal(const Matrix3& g)
{
  const Matrix3 b = g.trace() * Matrix3::Identity() - 0.5 * (g + g.transpose());
  Eigen::Matrix<double, 1, 6> row;
  row << -b(0, 0), -b(1, 1), -b(2, 2), -2 * b(0, 1), -2 * b(1, 2), -2 * b(2, 0);
  return row;
}

std::string number(double v)
{
  char s[32];
  std::snprintf(s, sizeof s, "%.17g", v == 0 ? 0.0 : v); // no "-0"
  return s;
}

/// One Taylor expansion M(q) = m0 + sum_k q_k m1(:, :, k) of the SID.
struct Taylor
{
  std::string name;
  int nrow = 0, ncol = 0, nq = 0, structure = 3; ///< 3 full, 2 symmetric (lower triangle)
  Eigen::MatrixXd m0;
  std::vector<Eigen::MatrixXd> m1; ///< empty: order 0

  Taylor(std::string n, int rows, int cols, int q, int s = 3)
      : name(std::move(n)), nrow(rows), ncol(cols), nq(q), structure(s),
        m0(Eigen::MatrixXd::Zero(rows, cols))
  {
  }
  void first_order() { m1.assign(nq, Eigen::MatrixXd::Zero(nrow, ncol)); }

  void write(std::ostream& out, const std::string& indent) const
  {
    out << indent << name << "\n"
        << indent << "    order        = " << (m1.empty() ? 0 : 1) << "\n"
        << indent << "    nrow         = " << nrow << "\n"
        << indent << "    ncol         = " << ncol << "\n"
        << indent << "    nq           = " << (m1.empty() ? 0 : nq) << "\n"
        << indent << "    nqn          = 0\n"
        << indent << "    structure    = " << structure << "\n";
    for (int i = 0; i < nrow; ++i)
      for (int j = 0; j < ncol; ++j)
        if (structure != 2 || j <= i)
          out << indent << "    m0( " << i + 1 << ", " << j + 1 << ") = " << number(m0(i, j))
              << "\n";
    for (std::size_t k = 0; k < m1.size(); ++k)
      for (int i = 0; i < nrow; ++i)
        for (int j = 0; j < ncol; ++j)
          if (structure != 2 || j <= i)
            out << indent << "    m1( " << i + 1 << ", " << j + 1 << ", " << k + 1
                << ") = " << number(m1[k](i, j)) << "\n";
    out << indent << "end " << name << "\n";
  }
};
} // namespace

std::string sid_text(const ReducedBodyData& body, const SidOptions& options)
{
  const int dim = body.dim, nq = body.n_modes(), n = body.n_nodes();
  const auto c_x_psi = [&](int k) { return embed(body.c_x_psi[k]); };
  // C(psi_l, psi_k): the file's entry (l, k) at index l*m + k.
  const auto c_pp = [&](int l, int k) { return embed(body.c_psi_psi[l * nq + k]); };
  const Matrix3 c_xx = embed(body.c_xx);
  Vector3 s0 = Vector3::Zero();
  s0.head(dim) = body.mass * body.center_of_mass;

  std::ostringstream out;
  out << "part\n"
      << "new modal\n"
      << "refmod\n"
      << "    mass           = " << number(body.mass) << "\n"
      << "    nelastq        = " << nq << "\n";
  for (int k = 0; k < nq; ++k)
    out << "    ielastq(" << k + 1 << ") = mode " << k + 1 << ": " << body.mode_kinds[k] << ", "
        << number(body.frequencies_hz(k)) << " Hz\n";
  out << "end refmod\n";

  // ---- frame: one node-fixed frame per written node
  std::vector<int> nodes = options.nodes;
  if (nodes.empty())
    for (int i = 0; i < n; ++i)
      nodes.push_back(i);
  out << "new frame\n";
  for (std::size_t s = 0; s < nodes.size(); ++s)
  {
    const int i = nodes[s];
    if (i < 0 || i >= n)
      throw InputError("SID export", "node " + std::to_string(i) + " is not a node of the body");
    Taylor origin("origin", 3, 1, nq), phi("phi", 3, nq, nq), psi("psi", 3, nq, nq),
        ap("AP", 3, 3, nq);
    origin.first_order();
    origin.m0.topRows(dim) = body.nodes.row(i).transpose();
    for (int k = 0; k < nq; ++k)
    {
      const Eigen::VectorXd shape = body.psi.block(dim * i, k, dim, 1);
      origin.m1[k].topRows(dim) = shape;
      phi.m0.block(0, k, dim, 1) = shape;
    }
    ap.m0 = Matrix3::Identity();
    out << "new node = " << s + 1 << "\n"
        << "    rframe = body ref\n"
        << "    fe node = " << i << "\n";
    origin.write(out, "    ");
    phi.write(out, "    ");
    psi.write(out, "    ");
    ap.write(out, "    ");
    out << "end node\n";
  }
  out << "end frame\n";

  // ---- mass invariants
  Taylor mdcm("mdCM", 3, 1, nq);
  mdcm.first_order();
  mdcm.m0 = s0;
  for (int k = 0; k < nq; ++k)
    mdcm.m1[k].topRows(dim) = body.translation_coupling.col(k);

  Taylor j("J", 3, 3, nq, 2);
  j.first_order();
  j.m0 = inertia_form(c_xx);
  for (int k = 0; k < nq; ++k)
    j.m1[k] = inertia_form(c_x_psi(k) + c_x_psi(k).transpose());

  Taylor ct("Ct", nq, 3, nq);
  for (int k = 0; k < nq; ++k)
    ct.m0.block(k, 0, 1, dim) = body.translation_coupling.col(k).transpose();

  Taylor cr("Cr", nq, 3, nq);
  cr.first_order();
  for (int k = 0; k < nq; ++k)
  {
    cr.m0.row(k) = axial(c_x_psi(k)).transpose();
    for (int l = 0; l < nq; ++l)
      cr.m1[l].row(k) = axial(c_pp(l, k)).transpose();
  }

  Taylor me("Me", nq, nq, nq, 2);
  me.m0 = body.mass_matrix;

  // Gr block k = -2 sum Ms u~ psi_k~ with a~ b~ = b a^T - (a.b) 1.
  const auto gyro = [](const Matrix3& c) // c = C(a, b): -2 sum Ms a~ b~
  { return Matrix3(-2 * (c.transpose() - c.trace() * Matrix3::Identity())); };
  Taylor gr("Gr", 3, 3 * nq, nq);
  gr.first_order();
  for (int k = 0; k < nq; ++k)
  {
    gr.m0.block(0, 3 * k, 3, 3) = gyro(c_x_psi(k));
    for (int l = 0; l < nq; ++l)
      gr.m1[l].block(0, 3 * k, 3, 3) = gyro(c_pp(l, k));
  }

  // Ge(j, 3k + a) = 2 axial_a(C(psi_k, psi_j)).
  Taylor ge("Ge", nq, 3 * nq, nq);
  for (int jj = 0; jj < nq; ++jj)
    for (int k = 0; k < nq; ++k)
      ge.m0.block(jj, 3 * k, 1, 3) = 2 * axial(c_pp(k, jj)).transpose();

  Taylor oe("Oe", nq, 6, nq);
  oe.first_order();
  for (int k = 0; k < nq; ++k)
  {
    oe.m0.row(k) = centrifugal(c_x_psi(k));
    for (int l = 0; l < nq; ++l)
      oe.m1[l].row(k) = centrifugal(c_pp(l, k));
  }

  Taylor ksigma("ksigma", nq, 1, nq);
  Taylor ke("Ke", nq, nq, nq, 2);
  ke.m0 = body.stiffness_matrix;
  Taylor de("De", nq, nq, nq);

  for (const Taylor* t : {&mdcm, &j, &ct, &cr, &me, &gr, &ge, &oe, &ksigma, &ke, &de})
    t->write(out, "");
  out << "end modal\n"
      << "end part\n";
  return out.str();
}

void write_sid(const std::string& path, const ReducedBodyData& body, const SidOptions& options)
{
  const std::string text = sid_text(body, options);
  AtomicOutput output(path);
  {
    std::ofstream out(output.temporary_path());
    out << text;
    if (!out)
      throw InputError(path, "cannot write");
  }
  output.commit();
}
} // namespace chipflex
