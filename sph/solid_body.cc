#include "sph/solid_body.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace chipflex::sph
{
namespace
{
/// A gate of a few hundred particles sub-steps ~10^5 times: below this size the cost of
/// starting a parallel region every sub-step exceeds the work.
constexpr std::size_t parallel_threshold = 4000;
} // namespace

double SolidMaterial::wave_speed() const
{
  return std::sqrt((bulk_modulus() + 4.0 / 3.0 * shear_modulus()) / density);
}

template <int dim>
SolidBody<dim>::SolidBody(const SolidMaterial& material, double spacing, double smoothing_length)
    : material_(material), spacing_(spacing), h_(smoothing_length)
{
  if (!(material.density > 0) || !(material.youngs_modulus > 0) ||
      !(material.poisson_ratio > -1 && material.poisson_ratio < 0.5))
    throw std::invalid_argument("SolidBody: density and E must be > 0, -1 < nu < 0.5");
  if (!(spacing > 0) || !(smoothing_length > 0))
    throw std::invalid_argument("SolidBody: spacing and smoothing length must be > 0");
  // Wendland C2, support 2h (the same kernel as the fluid).
  kernel_factor_ = dim == 2 ? 7.0 / (4 * M_PI * h_ * h_) : 21.0 / (16 * M_PI * h_ * h_ * h_);
  w_dp_ = kernel(spacing_);
  margin_ = 0.3 * spacing_;
}

template <int dim>
double SolidBody<dim>::kernel(double r) const
{
  const double q = r / h_;
  if (q >= 2)
    return 0;
  const double a = 1 - 0.5 * q;
  return kernel_factor_ * a * a * a * a * (2 * q + 1);
}

template <int dim>
double SolidBody<dim>::kernel_derivative(double r) const
{
  const double q = r / h_;
  if (q >= 2)
    return 0;
  const double a = 1 - 0.5 * q;
  return kernel_factor_ * (-5 * q) * a * a * a / h_;
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
  neighbour_start_.clear(); // forces a rebuild
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
  // All pairs: a gate has a few hundred to a few thousand particles and the list is
  // rebuilt only after a particle has moved by half the margin.
  const std::size_t n = x_.size();
  const double reach2 = std::pow(2 * h_ + margin_, 2);
  neighbour_start_.assign(n + 1, 0);
  neighbours_.clear();
  for (std::size_t i = 0; i < n; ++i)
  {
    for (std::size_t j = 0; j < n; ++j)
      if (j != i && (x_[i] - x_[j]).squaredNorm() < reach2)
        neighbours_.push_back(static_cast<int>(j));
    neighbour_start_[i + 1] = static_cast<int>(neighbours_.size());
  }
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

  // Momentum. Pairwise terms are symmetric in (i, j) and multiply the antisymmetric
  // kernel gradient, so the internal forces cancel in pairs.
  const double c = material_.wave_speed();
#pragma omp parallel for schedule(static) if (n > parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
  {
    Vector a = gravity_ + f_ext_[i] / mass_[i];
    const Tensor si = sigma_[i] / (rho_[i] * rho_[i]);
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
      Tensor T = si + sigma_[j] / (rho_[j] * rho_[j]) + f4 * (artificial_[i] + artificial_[j]);
      const double vr = (v_[i] - v_[j]).dot(r);
      if (vr < 0)
      {
        const double mu = h_ * vr / (d * d + 0.01 * h_ * h_);
        const double pi =
            (-material_.viscosity_alpha * c * mu + material_.viscosity_beta * mu * mu) /
            (0.5 * (rho_[i] + rho_[j]));
        T.diagonal().array() -= pi;
      }
      a += mass_[j] * (T * grad);
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
    for (int k = neighbour_start_[i]; k < neighbour_start_[i + 1]; ++k)
    {
      const int j = neighbours_[k];
      const Vector r = x_[i] - x_[j];
      const double d = r.norm();
      if (d >= support || d == 0)
        continue;
      const Vector grad = kernel_derivative(d) / d * r;
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
void SolidBody<dim>::step(double dt)
{
  // Symplectic Euler over the whole elastic state: the stress (like the position)
  // is advanced with the *new* velocity. Advancing it with the old one, as plain
  // explicit Euler does, grows the elastic waves at the usual CFL numbers.
  update_neighbours();
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
}

template class SolidBody<2>;
template class SolidBody<3>;
} // namespace chipflex::sph
