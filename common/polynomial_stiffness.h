#pragma once
// The reduced St Venant-Kirchhoff internal force of a body whose elastic displacement in its
// frame is u = Psi q: an exact cubic polynomial of the modal coordinates (Barbic & James
// 2005, "Real-time subspace integration for St. Venant-Kirchhoff deformable models", ACM
// TOG 24(3)):
//     V(q) = 1/2 K_ij q_i q_j + 1/3 Q_ijk q_i q_j q_k + 1/4 C_ijkl q_i q_j q_k q_l
//     f(q) = dV/dq = K q + Q:(q q) + C:(q q q)
//     K_t(q) = df/dq = K + 2 Q q + 3 C:(q q)
// Q and C are the third and fourth derivatives of the strain energy at q = 0 (divided by 2
// and 6), so they are fully symmetric: only the entries with sorted indices are stored,
// i <= j <= k and i <= j <= k <= l, in lexicographic order (docs/body_file_format.md).
// Evaluation goes through two dense unpacked forms built once: Q as m x (m m) and C as
// (m m) x (pairs k <= l), so the tangent costs m^2 m(m+1)/2 multiply-adds and the force
// follows from it (f = K q + (Q q) q + 1/3 (3 C q q) q) at O(m^2).

#include <Eigen/Dense>
#include <vector>

namespace chipflex
{
/// Number of sorted index tuples: m(m+1)(m+2)/6 for order 3, m(m+1)(m+2)(m+3)/24 for 4.
std::size_t n_sorted_triples(int m);
std::size_t n_sorted_quadruples(int m);

class PolynomialStiffness
{
public:
  PolynomialStiffness() = default;
  /// @param linear K (m x m); @param quadratic, cubic the packed sorted entries (their sizes
  /// must be n_sorted_triples(m), n_sorted_quadruples(m)); @param n_used evaluate only the
  /// first n_used coordinates (the leading principal part, as when a body keeps fewer modes)
  PolynomialStiffness(const Eigen::MatrixXd& linear, const std::vector<double>& quadratic,
                      const std::vector<double>& cubic, int n_used = -1);

  int size() const { return m_; }
  /// Internal force f(q) and, when `tangent` is not null, K_t(q).
  void evaluate(const Eigen::VectorXd& q, Eigen::Ref<Eigen::VectorXd> force,
                Eigen::MatrixXd* tangent = nullptr) const;
  /// Strain energy V(q).
  double energy(const Eigen::VectorXd& q) const;

  /// Packs a fully symmetric tensor given by an element function into sorted order.
  template <class F>
  static std::vector<double> pack_triples(int m, F&& entry)
  {
    std::vector<double> out;
    out.reserve(n_sorted_triples(m));
    for (int i = 0; i < m; ++i)
      for (int j = i; j < m; ++j)
        for (int k = j; k < m; ++k)
          out.push_back(entry(i, j, k));
    return out;
  }
  template <class F>
  static std::vector<double> pack_quadruples(int m, F&& entry)
  {
    std::vector<double> out;
    out.reserve(n_sorted_quadruples(m));
    for (int i = 0; i < m; ++i)
      for (int j = i; j < m; ++j)
        for (int k = j; k < m; ++k)
          for (int l = k; l < m; ++l)
            out.push_back(entry(i, j, k, l));
    return out;
  }

private:
  /// third- and fourth-order parts: g = Q q (m x m) and h = C:(q q) (m x m)
  void contract(const Eigen::VectorXd& q) const;

  int m_ = 0;
  Eigen::MatrixXd k_;     ///< m x m
  Eigen::MatrixXd q_mat_; ///< m x m^2: row i, column j + m k = Q_ijk
  Eigen::MatrixXd c_mat_; ///< m^2 x pairs: row i + m j, column pair (k <= l) = C_ijkl
  mutable Eigen::VectorXd pairs_, gvec_, hvec_;
  mutable Eigen::MatrixXd g_, h_;
};
} // namespace chipflex
