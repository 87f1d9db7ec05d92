#include "sph/solid_body.h"

#include "sph/neighbour_grid.h"
#include "sph/wendland_kernel.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace chipflex::sph
{
namespace
{
/// A gate of a few hundred particles sub-steps ~10^5 times: below this size the cost of
/// starting a parallel region every sub-step exceeds the work.
constexpr std::size_t parallel_threshold = 4000;

/// For each point, the indices of the other points closer than `reach`, ascending (the
/// order an all-pairs search gives, so the sums over them do not depend on the search):
/// start[i] ... start[i + 1] in `list`. A cell grid `reach` wide (sph/neighbour_grid.h)
/// over the points' bounding box finds them in O(n).
template <int dim>
void neighbours_within(const std::vector<Eigen::Matrix<double, dim, 1>>& x, double reach,
                       std::vector<int>& start, std::vector<int>& list)
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  const std::size_t n = x.size();
  start.assign(n + 1, 0);
  list.clear();
  if (n == 0)
    return;
  Vector lo = x[0], hi = x[0];
  for (const auto& p : x)
  {
    if (!p.allFinite())
      throw std::runtime_error("SPH solid: a particle's position is not finite (it blew up)");
    lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  }
  NeighbourGrid<dim> grid;
  grid.setup(lo - Vector::Constant(reach), hi + Vector::Constant(reach), reach);
  std::vector<std::uint32_t> cells(n), order, cell_start;
  for (std::size_t i = 0; i < n; ++i)
    cells[i] = grid.cell_of(x[i].data());
  grid.sort(cells, 0, n, order, cell_start);
  const double reach2 = reach * reach;
  std::vector<int> found;
  for (std::size_t i = 0; i < n; ++i)
  {
    found.clear();
    for (const std::int64_t offset : grid.row_offsets())
    {
      const std::int64_t first = std::int64_t(cells[i]) + offset;
      for (std::uint32_t k = cell_start[first]; k < cell_start[first + 3]; ++k)
      {
        const std::size_t j = order[k];
        if (j != i && (x[i] - x[j]).squaredNorm() < reach2)
          found.push_back(int(j));
      }
    }
    std::sort(found.begin(), found.end());
    list.insert(list.end(), found.begin(), found.end());
    start[i + 1] = int(list.size());
  }
}
} // namespace

void SolidMaterial::check() const
{
  const char* no_default = " (no default: every body states its material)";
  if (std::isnan(density))
    throw std::invalid_argument(std::string("SolidMaterial: density required") + no_default);
  if (std::isnan(youngs_modulus))
    throw std::invalid_argument(std::string("SolidMaterial: youngs_modulus required") + no_default);
  if (std::isnan(poisson_ratio))
    throw std::invalid_argument(std::string("SolidMaterial: poisson_ratio required") + no_default);
  if (!(density > 0) || !(youngs_modulus > 0) || !(poisson_ratio > -1 && poisson_ratio < 0.5))
    throw std::invalid_argument("SolidMaterial: density and E must be > 0, -1 < nu < 0.5");
}

double SolidMaterial::wave_speed() const
{
  return std::sqrt((bulk_modulus() + 4.0 / 3.0 * shear_modulus()) / density);
}

template <int dim>
SolidBody<dim>::SolidBody(const SolidMaterial& material, double spacing, double smoothing_length)
    : material_(material), spacing_(spacing), h_(smoothing_length)
{
  material.check();
  if (!(spacing > 0) || !(smoothing_length > 0))
    throw std::invalid_argument("SolidBody: spacing and smoothing length must be > 0");
  // Wendland C2, support 2h: the fluid's kernel (sph/wendland_kernel.h).
  w_dp_ = kernel(spacing_);
  margin_ = 0.3 * spacing_;
}

template <int dim>
double SolidBody<dim>::kernel(double r) const
{
  return WendlandKernel<dim>(h_).value(r);
}

template <int dim>
double SolidBody<dim>::kernel_derivative(double r) const
{
  return WendlandKernel<dim>(h_).gradient_over_r(r) * r;
}

template <int dim>
int SolidBody<dim>::add_particle(const Vector& position, double volume, bool fixed)
{
  x_.push_back(position);
  v_.push_back(Vector::Zero());
  f_ext_.push_back(Vector::Zero());
  rho_.push_back(material_.density);
  mass_.push_back(material_.density * volume);
  s_.push_back(Tensor::Zero());
  fixed_.push_back(fixed);
  x_ref_.push_back(position);
  volume_ref_.push_back(volume);
  neighbour_start_.clear(); // forces a rebuild
  reference_ready_ = false;
  return static_cast<int>(x_.size()) - 1;
}

template <int dim>
void SolidBody<dim>::set_external_forces(const std::vector<Vector>& forces)
{
  if (forces.size() != x_.size())
    throw std::logic_error("SolidBody: one external force per particle expected");
  f_ext_ = forces;
}

template <int dim>
double SolidBody<dim>::pressure(int i) const
{
  return material_.bulk_modulus() * (rho_[i] / material_.density - 1);
}

template <int dim>
double SolidBody<dim>::stable_time_step() const
{
  double v_max = 0;
  for (const auto& v : v_)
    v_max = std::max(v_max, v.norm());
  return material_.cfl * h_ / (material_.wave_speed() + v_max);
}

template <int dim>
void SolidBody<dim>::build_neighbour_list()
{
  // Rebuilt only after a particle has moved by half the margin.
  neighbours_within(x_, 2 * h_ + margin_, neighbour_start_, neighbours_);
  x_at_build_ = x_;
}

template <int dim>
void SolidBody<dim>::update_neighbours()
{
  const std::size_t n = x_.size();
  bool rebuild = neighbour_start_.size() != n + 1;
  for (std::size_t i = 0; !rebuild && i < n; ++i)
    rebuild = (x_[i] - x_at_build_[i]).squaredNorm() > 0.25 * margin_ * margin_;
  if (rebuild)
    build_neighbour_list();
}

template <int dim>
void SolidBody<dim>::compute_corrections()
{
  const std::size_t n = x_.size();
  correction_.assign(n, Tensor::Identity());
  n_uncorrected_ = 0;
  if (!material_.kernel_gradient_correction)
    return;
  const double support = 2 * h_;
  std::size_t fallbacks = 0;
#pragma omp parallel for schedule(static) reduction(+ : fallbacks) if (n > parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
  {
    // M_i = sum_j V_j grad_i W_ij (x_j - x_i)^T, the identity for a full kernel on a
    // regular lattice; the SPH gradient of a linear field u = G x is G M_i^T, so
    // C_i = M_i^-1 applied to every grad_i W_ij makes it exactly G.
    Tensor M = Tensor::Zero();
    for (int k = neighbour_start_[i]; k < neighbour_start_[i + 1]; ++k)
    {
      const int j = neighbours_[k];
      const Vector r = x_[i] - x_[j];
      const double d = r.norm();
      if (d >= support || d == 0)
        continue;
      const Vector grad = kernel_derivative(d) / d * r;
      M -= (mass_[j] / rho_[j]) * grad * r.transpose();
    }
    if (M.determinant() >= material_.correction_min_determinant)
      correction_[i] = M.inverse();
    else
      ++fallbacks;
  }
  n_uncorrected_ = fallbacks;
}

template <int dim>
void SolidBody<dim>::compute_accelerations()
{
  const std::size_t n = x_.size();
  acceleration_.resize(n);
  sigma_.resize(n);
  artificial_.resize(n);
  const double eps = material_.artificial_stress;
  const double support = 2 * h_;
  const Tensor identity = Tensor::Identity();

#pragma omp parallel for schedule(static) if (n > parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
  {
    const Tensor sigma = -pressure(static_cast<int>(i)) * identity + s_[i];
    sigma_[i] = sigma;
    // Artificial stress: on principal axes with tensile stress, R = -eps sigma / rho^2.
    Eigen::SelfAdjointEigenSolver<Tensor> principal(sigma);
    Vector r_principal;
    for (int a = 0; a < dim; ++a)
    {
      const double lambda = principal.eigenvalues()(a);
      r_principal(a) = lambda > 0 ? -eps * lambda / (rho_[i] * rho_[i]) : 0.0;
    }
    artificial_[i] =
        principal.eigenvectors() * r_principal.asDiagonal() * principal.eigenvectors().transpose();
  }

  // Momentum. The pair force m_i m_j (T_i C_i + T_j C_j) grad_i W_ij is antisymmetric in
  // (i, j) (grad_j W_ji = -grad_i W_ij), so the internal forces cancel in pairs with the
  // correction too (Bonet & Lok 1999).
  const double c = material_.wave_speed();
#pragma omp parallel for schedule(static) if (n > parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
  {
    Vector a = gravity_ + f_ext_[i] / mass_[i];
    const Tensor si = sigma_[i] / (rho_[i] * rho_[i]);
    const Tensor& ci = correction_[i];
    for (int k = neighbour_start_[i]; k < neighbour_start_[i + 1]; ++k)
    {
      const int j = neighbours_[k];
      const Vector r = x_[i] - x_[j];
      const double d = r.norm();
      if (d >= support || d == 0)
        continue;
      const Vector grad = kernel_derivative(d) / d * r; // grad_i W_ij
      const double f = kernel(d) / w_dp_;
      const double f4 = (f * f) * (f * f);
      const Tensor& cj = correction_[j];
      const Tensor Ti = si + f4 * artificial_[i];
      const Tensor Tj = sigma_[j] / (rho_[j] * rho_[j]) + f4 * artificial_[j];
      Vector pair = Ti * (ci * grad) + Tj * (cj * grad);
      const double vr = (v_[i] - v_[j]).dot(r);
      if (vr < 0)
      {
        const double mu = h_ * vr / (d * d + 0.01 * h_ * h_);
        const double pi =
            (-material_.viscosity_alpha * c * mu + material_.viscosity_beta * mu * mu) /
            (0.5 * (rho_[i] + rho_[j]));
        pair -= pi * 0.5 * (ci + cj) * grad;
      }
      a += mass_[j] * pair;
    }
    acceleration_[i] = a;
  }
}

template <int dim>
void SolidBody<dim>::compute_stress_rates()
{
  const std::size_t n = x_.size();
  density_rate_.resize(n);
  stress_rate_.resize(n);
  const double G = material_.shear_modulus();
  const double support = 2 * h_;
  const Tensor identity = Tensor::Identity();

#pragma omp parallel for schedule(static) if (n > parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
  {
    Tensor L = Tensor::Zero(); // L(a, b) = dv_a / dx_b
    double drho = 0;
    const Tensor& ci = correction_[i];
    for (int k = neighbour_start_[i]; k < neighbour_start_[i + 1]; ++k)
    {
      const int j = neighbours_[k];
      const Vector r = x_[i] - x_[j];
      const double d = r.norm();
      if (d >= support || d == 0)
        continue;
      const Vector grad = ci * (kernel_derivative(d) / d * r);
      const Vector vij = v_[i] - v_[j];
      drho += mass_[j] * vij.dot(grad);
      L -= (mass_[j] / rho_[j]) * vij * grad.transpose();
    }
    const Tensor strain_rate = 0.5 * (L + L.transpose());
    const Tensor spin = 0.5 * (L - L.transpose());
    // Plane strain in 2D: the out-of-plane strain rate is zero, so the in-plane trace
    // is the full trace and the deviator subtracts a third of it. Jaumann rate:
    // dS/dt = 2G dev(D) + W S - S W (Gray et al. 2001, eq. 9).
    const double trace = strain_rate.trace();
    density_rate_[i] = drho;
    stress_rate_[i] = 2 * G * (strain_rate - trace / 3.0 * identity) + spin * s_[i] - s_[i] * spin;
  }
}

template <int dim>
void SolidBody<dim>::setup_reference()
{
  // Neighbours within the support in the reference configuration, for good.
  const std::size_t n = x_ref_.size();
  neighbours_within(x_ref_, 2 * h_, neighbour_start_, neighbours_);
  reference_gradient_.clear();
  for (std::size_t i = 0; i < n; ++i)
    for (int k = neighbour_start_[i]; k < neighbour_start_[i + 1]; ++k)
    {
      const Vector r = x_ref_[i] - x_ref_[neighbours_[k]];
      const double d = r.norm();
      reference_gradient_.push_back(kernel_derivative(d) / d * r); // grad_0,i W_ij
    }
  correction_.assign(n, Tensor::Identity());
  n_uncorrected_ = 0;
  if (material_.kernel_gradient_correction)
    for (std::size_t i = 0; i < n; ++i)
    {
      Tensor M = Tensor::Zero(); // sum_j V_j grad_0 W_ij (X_j - X_i)^T
      for (int k = neighbour_start_[i]; k < neighbour_start_[i + 1]; ++k)
      {
        const int j = neighbours_[k];
        M += volume_ref_[j] * reference_gradient_[k] * (x_ref_[j] - x_ref_[i]).transpose();
      }
      if (M.determinant() >= material_.correction_min_determinant)
        correction_[i] = M.inverse();
      else
        ++n_uncorrected_;
    }
  piola_.assign(n, Tensor::Zero());
  deformation_.assign(n, Tensor::Identity());
  acceleration_.assign(n, Vector::Zero());
  reference_ready_ = true;
}

template <int dim>
void SolidBody<dim>::step_total_lagrangian(double dt)
{
  if (!reference_ready_)
    setup_reference();
  const std::size_t n = x_.size();
  const double G = material_.shear_modulus();
  const double lambda = material_.bulk_modulus() - 2.0 / 3.0 * G; // 3D Lame: plane strain
  const double rho0 = material_.density;
  const Tensor identity = Tensor::Identity();

  // Deformation gradient from the displacements u = x - X (so that a particle whose
  // correction fell back is still stress free at rest), then S and P = F S.
#pragma omp parallel for schedule(static) if (n > parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
  {
    const Vector ui = x_[i] - x_ref_[i];
    Tensor H = Tensor::Zero(); // displacement gradient
    for (int k = neighbour_start_[i]; k < neighbour_start_[i + 1]; ++k)
    {
      const int j = neighbours_[k];
      H += volume_ref_[j] * (x_[j] - x_ref_[j] - ui) *
           (correction_[i] * reference_gradient_[k]).transpose();
    }
    const Tensor F = identity + H;
    deformation_[i] = F;
    const Tensor E = 0.5 * (F.transpose() * F - identity);
    const Tensor S = lambda * E.trace() * identity + 2 * G * E;
    piola_[i] = F * S;
    const double J = F.determinant();
    rho_[i] = rho0 / J;
    const Tensor cauchy = piola_[i] * F.transpose() / J;
    // Plane strain: sigma_zz = lambda tr(E) (in-plane E, E_zz = 0) enters the mean stress.
    const double mean = (cauchy.trace() + (dim == 2 ? lambda * E.trace() / J : 0.0)) / 3.0;
    s_[i] = cauchy - mean * identity;
  }

  // Forces: the derivative of sum_i V_i psi(F_i), f_i = sum_j V_i V_j (P_i C_i + P_j C_j)
  // grad_0 W_ij (antisymmetric in (i, j)), plus Monaghan's viscosity on approaching pairs
  // in the current configuration.
  const double c = material_.wave_speed(), support = 2 * h_;
  const double hourglass = 0.5 * material_.hourglass_control * material_.youngs_modulus;
#pragma omp parallel for schedule(static) if (n > parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
  {
    Vector a = gravity_ + f_ext_[i] / mass_[i];
    const Tensor PCi = piola_[i] * correction_[i];
    const Tensor Fi = deformation_[i];
    for (int k = neighbour_start_[i]; k < neighbour_start_[i + 1]; ++k)
    {
      const int j = neighbours_[k];
      a += (volume_ref_[i] * volume_ref_[j] / mass_[i]) *
           ((PCi + piola_[j] * correction_[j]) * reference_gradient_[k]);
      const Vector r = x_[i] - x_[j];
      const double d = r.norm();
      if (hourglass > 0 && d > 0)
      {
        // Ganzenmueller 2015, eq. 20-22: delta = (F X_ij - x_ij) . x_ij / |x_ij| seen from
        // both ends; a positive one means j sits closer than F predicts: push apart.
        const Vector X = x_ref_[j] - x_ref_[i], e = -r / d;
        const double R2 = X.squaredNorm();
        const double delta = (Fi * X + r).dot(e) + (deformation_[j] * X + r).dot(e);
        a -= hourglass * volume_ref_[i] * volume_ref_[j] * kernel(std::sqrt(R2)) / R2 * delta /
             mass_[i] * e;
      }
      const double vr = (v_[i] - v_[j]).dot(r);
      if (vr < 0 && d < support && d > 0)
      {
        const double mu = h_ * vr / (d * d + 0.01 * h_ * h_);
        const double pi =
            (-material_.viscosity_alpha * c * mu + material_.viscosity_beta * mu * mu) /
            (0.5 * (rho_[i] + rho_[j]));
        a -= mass_[j] * pi * (kernel_derivative(d) / d) * r;
      }
    }
    acceleration_[i] = a;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (fixed_[i])
      clamp_impulse_ += dt * mass_[i] * acceleration_[i];
    else
    {
      v_[i] += dt * acceleration_[i];
      x_[i] += dt * v_[i];
    }
  }
}

template <int dim>
void SolidBody<dim>::step(double dt)
{
  if (material_.formulation == SolidFormulation::total_lagrangian)
  {
    step_total_lagrangian(dt);
    return;
  }
  // Symplectic Euler over the whole elastic state: the stress (like the position)
  // is advanced with the *new* velocity. Advancing it with the old one, as plain
  // explicit Euler does, grows the elastic waves at the usual CFL numbers.
  update_neighbours();
  compute_corrections();
  compute_accelerations();
  const std::size_t n = x_.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    if (fixed_[i])
    {
      // The clamp takes the force its neighbours put on it: keep it as an impulse so
      // that momentum bookkeeping closes.
      clamp_impulse_ += dt * mass_[i] * acceleration_[i];
    }
    else
    {
      v_[i] += dt * acceleration_[i];
      x_[i] += dt * v_[i];
    }
  }
  compute_stress_rates();
  for (std::size_t i = 0; i < n; ++i)
  {
    rho_[i] += dt * density_rate_[i];
    s_[i] += dt * stress_rate_[i];
  }
}

template <int dim>
int SolidBody<dim>::advance(double dt)
{
  if (dt <= 0)
    return 0;
  const int n_steps = std::max(1, static_cast<int>(std::ceil(dt / stable_time_step() - 1e-9)));
  const double sub = dt / n_steps;
  for (int k = 0; k < n_steps; ++k)
    step(sub);
  return n_steps;
}

template <int dim>
typename SolidBody<dim>::Vector SolidBody<dim>::linear_momentum() const
{
  Vector p = clamp_impulse_;
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (!fixed_[i])
      p += mass_[i] * v_[i];
  return p;
}

template <int dim>
std::vector<double> SolidBody<dim>::state() const
{
  std::vector<double> out;
  out.reserve(x_.size() * (2 * dim + 1 + dim * dim) + dim);
  for (std::size_t i = 0; i < x_.size(); ++i)
  {
    out.insert(out.end(), x_[i].data(), x_[i].data() + dim);
    out.insert(out.end(), v_[i].data(), v_[i].data() + dim);
    out.push_back(rho_[i]);
    out.insert(out.end(), s_[i].data(), s_[i].data() + dim * dim);
  }
  out.insert(out.end(), clamp_impulse_.data(), clamp_impulse_.data() + dim);
  return out;
}

template <int dim>
void SolidBody<dim>::restore(const std::vector<double>& state)
{
  const std::size_t per = 2 * dim + 1 + dim * dim;
  if (state.size() != x_.size() * per + dim)
    throw std::invalid_argument("SolidBody::restore: state of " + std::to_string(state.size()) +
                                " values does not fit " + std::to_string(x_.size()) + " particles");
  const double* p = state.data();
  for (std::size_t i = 0; i < x_.size(); ++i)
  {
    std::copy(p, p + dim, x_[i].data());
    std::copy(p + dim, p + 2 * dim, v_[i].data());
    rho_[i] = p[2 * dim];
    std::copy(p + 2 * dim + 1, p + per, s_[i].data());
    p += per;
  }
  std::copy(p, p + dim, clamp_impulse_.data());
  neighbour_start_.clear();
  reference_ready_ = false; // rebuilt from the reference positions, which do not change
}

template class SolidBody<2>;
template class SolidBody<3>;
} // namespace chipflex::sph
