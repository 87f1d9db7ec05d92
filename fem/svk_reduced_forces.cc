#include "fem/svk_reduced_forces.h"

#include "common/polynomial_stiffness.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <mpi.h>
#include <stdexcept>

namespace chipflex::fem
{
namespace
{
template <int dim>
using Mat = Eigen::Matrix<double, dim, dim>;
template <int dim>
constexpr int n_mandel = dim == 2 ? 3 : 6;
template <int dim>
using MandelVector = Eigen::Matrix<double, n_mandel<dim>, 1>;

/// Mandel vector of a symmetric matrix: normal entries, then sqrt(2) times the shear ones,
/// so that X : Y is the dot product.
template <int dim>
MandelVector<dim> mandel(const Mat<dim>& x)
{
  MandelVector<dim> v;
  if constexpr (dim == 2)
    v << x(0, 0), x(1, 1), M_SQRT2 * x(0, 1);
  else
    v << x(0, 0), x(1, 1), x(2, 2), M_SQRT2 * x(1, 2), M_SQRT2 * x(0, 2), M_SQRT2 * x(0, 1);
  return v;
}

void sum_over_processes(double* data, std::size_t size, MPI_Comm communicator)
{
  if (size)
    MPI_Allreduce(MPI_IN_PLACE, data, static_cast<int>(size), MPI_DOUBLE, MPI_SUM, communicator);
}

/// Walks the body's own cells and hands, per quadrature point, the displacement
/// gradients H_a of every column of `fields`, the scalar shape gradients, the cell's
/// nodes and JxW to `visit`.
template <int dim, class Visit>
void for_each_quadrature_point(const ElasticBody<dim>& body, const Eigen::MatrixXd& fields,
                               Visit&& visit)
{
  const Quadrature<dim> quadrature = body.mesh.simplex
                                         ? Quadrature<dim>(QGaussSimplex<dim>(body.degree + 1))
                                         : Quadrature<dim>(QGauss<dim>(body.degree + 1));
  const auto& fe = *body.fe;
  FEValues<dim> fe_values(*body.mapping, fe, quadrature, update_gradients | update_JxW_values);
  const unsigned int n_base = fe.base_element(0).n_dofs_per_cell();
  const int m = fields.cols();
  std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
  std::vector<int> nodes(n_base);
  Eigen::MatrixXd grad(n_base, dim), cell_fields(n_base * dim, m);
  std::vector<Mat<dim>> h(m);
  for (const auto& cell : body.dof_handler.active_cell_iterators())
  {
    if (cell->subdomain_id() != body.this_process)
      continue;
    fe_values.reinit(cell);
    cell->get_dof_indices(local);
    for (unsigned int b = 0; b < n_base; ++b)
    {
      nodes[b] = body.node_of_dof[local[fe.component_to_system_index(0, b)]];
      cell_fields.middleRows(b * dim, dim) = fields.middleRows(nodes[b] * dim, dim);
    }
    for (unsigned int q = 0; q < quadrature.size(); ++q)
    {
      for (unsigned int b = 0; b < n_base; ++b)
      {
        const auto g = fe_values.shape_grad(fe.component_to_system_index(0, b), q);
        for (int d = 0; d < dim; ++d)
          grad(b, d) = g[d];
      }
      // H_a(c, d) = sum_b field_a(node b, c) dN_b/dx_d
      for (int a = 0; a < m; ++a)
      {
        h[a].setZero();
        for (unsigned int b = 0; b < n_base; ++b)
          h[a] += cell_fields.block(b * dim, a, dim, 1) * grad.row(b);
      }
      visit(h, grad, nodes, fe_values.JxW(q));
    }
  }
}

template <int dim>
Mat<dim> stress(const Mat<dim>& e, double lambda, double mu)
{
  return 2 * mu * e + lambda * e.trace() * Mat<dim>::Identity();
}
} // namespace

template <int dim>
SvkPolynomial svk_polynomial(const ElasticBody<dim>& body, const Eigen::MatrixXd& basis)
{
  constexpr int nv = n_mandel<dim>;
  const int m = basis.cols(), n_pairs = m * (m + 1) / 2;
  const double lambda = body.material.lame_lambda(dim), mu = body.material.shear_modulus();
  Eigen::Matrix<double, nv, nv> elasticity = 2 * mu * Eigen::Matrix<double, nv, nv>::Identity();
  elasticity.template topLeftCorner<dim, dim>().array() += lambda;
  const Eigen::LLT<Eigen::Matrix<double, nv, nv>> cholesky(elasticity);
  if (cholesky.info() != Eigen::Success)
    throw std::logic_error("svk_polynomial: the elasticity matrix is not positive definite");
  const Eigen::Matrix<double, nv, nv> u = cholesky.matrixU();                  // D = U^T U
  auto pair = [m](int k, int l) { return k * m - k * (k - 1) / 2 + (l - k); }; // k <= l

  // Rows of weighted strains, a batch of quadrature points at a time, so the sums are
  // large matrix products: G += Y^T Y (pairs x pairs), LB += Z^T Y, K += Z^T Z.
  const int batch = 64 * nv;
  Eigen::MatrixXd y(batch, n_pairs), z(batch, m);
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(n_pairs, n_pairs),
                  lb = Eigen::MatrixXd::Zero(m, n_pairs), k = Eigen::MatrixXd::Zero(m, m);
  int rows = 0;
  auto flush = [&]()
  {
    if (!rows)
      return;
    g.template selfadjointView<Eigen::Lower>().rankUpdate(y.topRows(rows).transpose());
    lb.noalias() += z.topRows(rows).transpose() * y.topRows(rows);
    k.noalias() += z.topRows(rows).transpose() * z.topRows(rows);
    rows = 0;
  };
  for_each_quadrature_point<dim>(
      body, basis,
      [&](const std::vector<Mat<dim>>& h, const Eigen::MatrixXd&, const std::vector<int>&,
          double jxw)
      {
        const double w = std::sqrt(jxw);
        for (int a = 0; a < m; ++a)
          z.block(rows, a, nv, 1) = w * (u * mandel<dim>(0.5 * (h[a] + h[a].transpose())));
        for (int a = 0; a < m; ++a)
          for (int b = a; b < m; ++b)
          {
            const Mat<dim> hab = h[a].transpose() * h[b];
            y.block(rows, pair(a, b), nv, 1) =
                w * (u * mandel<dim>(Mat<dim>(0.5 * (hab + hab.transpose()))));
          }
        rows += nv;
        if (rows == batch)
          flush();
      });
  flush();
  g = g.template selfadjointView<Eigen::Lower>();
  sum_over_processes(g.data(), g.size(), body.communicator);
  sum_over_processes(lb.data(), lb.size(), body.communicator);
  sum_over_processes(k.data(), k.size(), body.communicator);

  SvkPolynomial result;
  result.linear = 0.5 * (k + k.transpose());
  result.quadratic = PolynomialStiffness::pack_triples(
      m, [&](int i, int j, int l)
      { return 0.5 * (lb(i, pair(j, l)) + lb(j, pair(i, l)) + lb(l, pair(i, j))); });
  result.cubic = PolynomialStiffness::pack_quadruples(
      m,
      [&](int i, int j, int l, int n)
      {
        return (g(pair(i, j), pair(l, n)) + g(pair(i, l), pair(j, n)) + g(pair(i, n), pair(j, l))) /
               6;
      });
  return result;
}

template <int dim>
std::vector<Eigen::VectorXd> svk_second_order_forces(const ElasticBody<dim>& body,
                                                     const Eigen::MatrixXd& modes,
                                                     const std::vector<std::pair<int, int>>& pairs)
{
  const double lambda = body.material.lame_lambda(dim), mu = body.material.shear_modulus();
  const int m = modes.cols();
  const Eigen::Index size = modes.rows();
  std::vector<Eigen::VectorXd> forces(pairs.size(), Eigen::VectorXd::Zero(size));
  std::vector<Mat<dim>> s(m);
  for_each_quadrature_point<dim>(
      body, modes,
      [&](const std::vector<Mat<dim>>& h, const Eigen::MatrixXd& grad,
          const std::vector<int>& nodes, double jxw)
      {
        for (int a = 0; a < m; ++a)
          s[a] = stress<dim>(Mat<dim>(0.5 * (h[a] + h[a].transpose())), lambda, mu);
        for (std::size_t p = 0; p < pairs.size(); ++p)
        {
          const auto [i, j] = pairs[p];
          const Mat<dim> hij = h[i].transpose() * h[j];
          const Mat<dim> t = stress<dim>(Mat<dim>(0.5 * (hij + hij.transpose())), lambda, mu) +
                             h[j] * s[i] + h[i] * s[j];
          for (std::size_t b = 0; b < nodes.size(); ++b)
            forces[p].template segment<dim>(nodes[b] * dim) += jxw * (t * grad.row(b).transpose());
        }
      });
  for (auto& f : forces)
  {
    sum_over_processes(f.data(), f.size(), body.communicator);
    if (body.is_clamped())
      for (const int node : body.node_sets.at(body.clamp_group))
        f.template segment<dim>(node * dim).setZero();
  }
  return forces;
}

template SvkPolynomial svk_polynomial<2>(const ElasticBody<2>&, const Eigen::MatrixXd&);
template SvkPolynomial svk_polynomial<3>(const ElasticBody<3>&, const Eigen::MatrixXd&);
template std::vector<Eigen::VectorXd>
svk_second_order_forces<2>(const ElasticBody<2>&, const Eigen::MatrixXd&,
                           const std::vector<std::pair<int, int>>&);
template std::vector<Eigen::VectorXd>
svk_second_order_forces<3>(const ElasticBody<3>&, const Eigen::MatrixXd&,
                           const std::vector<std::pair<int, int>>&);
} // namespace chipflex::fem
