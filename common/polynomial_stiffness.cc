#include "common/polynomial_stiffness.h"

#include "common/input_error.h"

#include <algorithm>
#include <array>

namespace chipflex
{
std::size_t n_sorted_triples(int m)
{
  const std::size_t n = m;
  return n * (n + 1) * (n + 2) / 6;
}

std::size_t n_sorted_quadruples(int m)
{
  const std::size_t n = m;
  return n * (n + 1) * (n + 2) * (n + 3) / 24;
}

namespace
{
/// The file's m from the packed size of the triples (m^3/6 grows fast: a short search).
int modes_of(std::size_t triples)
{
  int m = 0;
  while (n_sorted_triples(m) < triples)
    ++m;
  return m;
}
} // namespace

PolynomialStiffness::PolynomialStiffness(const Eigen::MatrixXd& linear,
                                         const std::vector<double>& quadratic,
                                         const std::vector<double>& cubic, int n_used)
{
  const int m_file = static_cast<int>(linear.rows());
  if (linear.cols() != m_file || quadratic.size() != n_sorted_triples(m_file) ||
      cubic.size() != n_sorted_quadruples(m_file) || modes_of(quadratic.size()) != m_file)
    throw InputError("PolynomialStiffness", "coefficient counts do not match the number of modes");
  const int m = n_used < 0 ? m_file : std::min(n_used, m_file);
  m_ = m;
  k_ = linear.topLeftCorner(m, m);
  q_mat_ = Eigen::MatrixXd::Zero(m, m * m);
  const int n_pairs = m * (m + 1) / 2;
  c_mat_ = Eigen::MatrixXd::Zero(m * m, n_pairs);
  auto pair = [m](int k, int l) { return k * m - k * (k - 1) / 2 + (l - k); }; // k <= l
  std::size_t at = 0;
  for (int i = 0; i < m_file; ++i)
    for (int j = i; j < m_file; ++j)
      for (int k = j; k < m_file; ++k, ++at)
      {
        if (k >= m)
          continue;
        std::array<int, 3> p{i, j, k};
        do
          q_mat_(p[0], p[1] + m * p[2]) = quadratic[at];
        while (std::next_permutation(p.begin(), p.end()));
      }
  at = 0;
  for (int i = 0; i < m_file; ++i)
    for (int j = i; j < m_file; ++j)
      for (int k = j; k < m_file; ++k)
        for (int l = k; l < m_file; ++l, ++at)
        {
          if (l >= m)
            continue;
          std::array<int, 4> p{i, j, k, l};
          do
            if (p[2] <= p[3])
              c_mat_(p[0] + m * p[1], pair(p[2], p[3])) = cubic[at];
          while (std::next_permutation(p.begin(), p.end()));
        }
  pairs_.resize(n_pairs);
  gvec_.resize(m * m);
  hvec_.resize(m * m);
  g_.resize(m, m);
  h_.resize(m, m);
}

void PolynomialStiffness::contract(const Eigen::VectorXd& q) const
{
  const int m = m_;
  int p = 0;
  for (int k = 0; k < m; ++k)
  {
    pairs_(p++) = q(k) * q(k);
    for (int l = k + 1; l < m; ++l)
      pairs_(p++) = 2 * q(k) * q(l);
  }
  gvec_.noalias() = Eigen::Map<const Eigen::MatrixXd>(q_mat_.data(), m * m, m) * q;
  hvec_.noalias() = c_mat_ * pairs_;
  g_ = Eigen::Map<const Eigen::MatrixXd>(gvec_.data(), m, m);
  h_ = Eigen::Map<const Eigen::MatrixXd>(hvec_.data(), m, m);
}

void PolynomialStiffness::evaluate(const Eigen::VectorXd& q, Eigen::Ref<Eigen::VectorXd> force,
                                   Eigen::MatrixXd* tangent) const
{
  contract(q);
  force.noalias() = k_ * q;
  force.noalias() += g_ * q;
  force.noalias() += h_ * q;
  if (tangent)
    *tangent = k_ + 2 * g_ + 3 * h_;
}

double PolynomialStiffness::energy(const Eigen::VectorXd& q) const
{
  contract(q);
  return 0.5 * q.dot(k_ * q) + q.dot(g_ * q) / 3 + 0.25 * q.dot(h_ * q);
}
} // namespace chipflex
