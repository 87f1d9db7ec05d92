#pragma once
// The fluid's density and velocity at a point by a first-order moving-least-squares fit
// (used at mirror points: the open boundaries' buffers, sph/fluid_solver_open_boundaries.cc,
// and the no-slip dummy walls, sph/fluid_solver_no_slip.cc). Outside the force loop.

#include "sph/neighbour_grid.h"
#include "sph/particle_arrays.h"
#include "sph/wendland_kernel.h"

#include <Eigen/LU>
#include <cmath>
#include <vector>

namespace chipflex::sph
{
/// A first-order moving-least-squares fit of the density and velocity of the fluid
/// (not buffer) particles around x_g: the value at x_g and its gradient. Weights
/// V_j W(|x_j - x_g|), basis (1, (x_j - x_g)/h). With too few neighbours for a gradient
/// (ill-conditioned moments) the Shepard average; with none, nothing.
template <int dim>
struct MirrorFit
{
  bool valid = false;
  double density = 0;
  Eigen::Matrix<double, dim, 1> density_gradient = Eigen::Matrix<double, dim, 1>::Zero();
  Eigen::Matrix<double, dim, 1> velocity = Eigen::Matrix<double, dim, 1>::Zero();
};

template <int dim>
inline MirrorFit<dim> fit_at(const ParticleArrays<dim>& p, const NeighbourGrid<dim>& grid,
                             const std::vector<std::uint32_t>& fluid_start,
                             const WendlandKernel<dim>& W, double mass,
                             const Eigen::Matrix<double, dim, 1>& xg, bool skip_buffers)
{
  using Moments = Eigen::Matrix<double, dim + 1, dim + 1>;
  using Values = Eigen::Matrix<double, dim + 1, dim + 1>; // columns: rho, v_0 .. v_dim-1
  MirrorFit<dim> fit;
  const std::uint32_t c = grid.cell_of(xg.data());
  if (c == NeighbourGrid<dim>::outside)
    return fit;
  const double h = W.h, support2 = 4 * h * h;
  Moments A = Moments::Zero();
  Values B = Values::Zero();
  for (int r = 0; r < NeighbourGrid<dim>::n_rows; ++r)
  {
    const std::int64_t base = std::int64_t(c) + grid.row_offsets()[r];
    for (std::uint32_t j = fluid_start[base]; j < fluid_start[base + 3]; ++j)
    {
      if (skip_buffers && p.zone[j])
        continue;
      Eigen::Matrix<double, dim + 1, 1> basis;
      basis[0] = 1;
      double r2 = 0;
      for (int d = 0; d < dim; ++d)
      {
        const double dx = p.position[d][j] - xg[d];
        basis[d + 1] = dx / h;
        r2 += dx * dx;
      }
      if (r2 >= support2)
        continue;
      const double w = W.value(std::sqrt(r2)) * mass / double(p.density[j]);
      Eigen::Matrix<double, 1, dim + 1> f;
      f[0] = p.density[j];
      for (int d = 0; d < dim; ++d)
        f[d + 1] = p.velocity[d][j];
      for (int a = 0; a <= dim; ++a)
        for (int b = 0; b <= dim; ++b)
        {
          A(a, b) += w * basis[a] * basis[b];
          B(a, b) += w * basis[a] * f[b];
        }
    }
  }
  // A full support has sum V W = 1; below a tenth the fit is not worth trusting.
  if (!(A(0, 0) > 0.1))
    return fit;
  fit.valid = true;
  // Hadamard ratio det(A) / prod(A_ii): 1 for independent moments, 0 for neighbours on
  // a line (no gradient across it).
  double diagonal = 1;
  for (int a = 0; a <= dim; ++a)
    diagonal *= A(a, a);
  const double det = A.determinant();
  if (diagonal > 0 && det > 1e-3 * diagonal)
  {
    const Moments inverse = A.inverse();
    Values C = Values::Zero();
    for (int a = 0; a <= dim; ++a)
      for (int b = 0; b <= dim; ++b)
        for (int k = 0; k <= dim; ++k)
          C(a, b) += inverse(a, k) * B(k, b);
    fit.density = C(0, 0);
    for (int d = 0; d < dim; ++d)
    {
      fit.density_gradient[d] = C(d + 1, 0) / h;
      fit.velocity[d] = C(0, d + 1);
    }
  }
  else
  {
    fit.density = B(0, 0) / A(0, 0);
    for (int d = 0; d < dim; ++d)
      fit.velocity[d] = B(0, d + 1) / A(0, 0);
  }
  return fit;
}
} // namespace chipflex::sph
