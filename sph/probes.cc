#include "sph/probes.h"

#include "sph/case_setup.h"
#include "sph/particle_exchange.h"
#include "sph/wendland_kernel.h"

#include <algorithm>
#include <cmath>

namespace chipflex::sph
{
namespace
{
/// Over MPI, each rank sums its own particles (ghosts skipped): the sums over the ranks
/// are the gauge's.
template <int dim>
void reduce_sums(const FluidSolver<dim>& fluid, double* sums, int n)
{
  if (const auto* exchange = fluid.exchange())
    exchange->sum(sums, n);
}
} // namespace

template <int dim>
double sample_pressure(const FluidSolver<dim>& fluid, const Eigen::Matrix<double, dim, 1>& x)
{
  const double h = fluid.parameters().smoothing_length();
  const WendlandKernel<dim> kernel(h);
  const auto& p = fluid.particles();
  double sum_w = 0, sum_pw = 0;
  for (std::size_t i = p.n_boundary; i < p.size(); ++i)
  {
    if (p.is_ghost(i))
      continue;
    double r2 = 0;
    for (int d = 0; d < dim; ++d)
      r2 += (p.position[d][i] - x[d]) * (p.position[d][i] - x[d]);
    if (r2 >= 4 * h * h)
      continue;
    const double vw = fluid.particle_mass() / p.density[i] * kernel.value(std::sqrt(r2));
    sum_w += vw;
    sum_pw += vw * fluid.pressure(i);
  }
  double sums[2] = {sum_w, sum_pw};
  reduce_sums(fluid, sums, 2);
  return sums[0] > 0 ? sums[1] / sums[0] : 0.0;
}

template <int dim>
double sample_water_height(const FluidSolver<dim>& fluid, const Eigen::Matrix<double, dim, 1>& x)
{
  const auto& par = fluid.parameters();
  const double h = par.smoothing_length();
  const int up = vertical_axis<dim>(par.gravity);
  const WendlandKernel<dim> kernel(h);
  const auto& p = fluid.particles();
  struct Near
  {
    double lateral2, elevation, volume;
  };
  std::vector<Near> near;
  for (std::size_t i = p.n_boundary; i < p.size(); ++i)
  {
    if (p.is_ghost(i))
      continue;
    double lateral2 = 0;
    for (int d = 0; d < dim; ++d)
      if (d != up)
        lateral2 += (p.position[d][i] - x[d]) * (p.position[d][i] - x[d]);
    if (lateral2 >= 4 * h * h)
      continue;
    near.push_back({lateral2, p.position[up][i], fluid.particle_mass() / p.density[i]});
  }
  // Over MPI the line crosses any number of slabs: every rank takes all their particles.
  if (const auto* exchange = fluid.exchange())
  {
    std::vector<double> mine;
    for (const auto& n : near)
      mine.insert(mine.end(), {n.lateral2, n.elevation, n.volume});
    const std::vector<double> all = exchange->all_gather(mine);
    near.clear();
    for (std::size_t k = 0; k + 2 < all.size(); k += 3)
      near.push_back({all[k], all[k + 1], all[k + 2]});
  }
  double lo = 1e300, hi = -1e300;
  for (const auto& n : near)
  {
    lo = std::min(lo, n.elevation);
    hi = std::max(hi, n.elevation);
  }
  if (near.empty())
    return x[up];
  double surface = lo - h;
  const double step = 0.25 * par.particle_spacing;
  for (double z = lo; z <= hi + 2 * h; z += step)
  {
    double fraction = 0;
    for (const auto& n : near)
    {
      const double r2 = n.lateral2 + (n.elevation - z) * (n.elevation - z);
      if (r2 < 4 * h * h)
        fraction += n.volume * kernel.value(std::sqrt(r2));
    }
    if (fraction >= 0.5)
      surface = z;
  }
  return surface;
}

double sample_flow_rate(const FluidSolver<2>& fluid, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b)
{
  const double length = (b - a).norm();
  if (!(length > 0))
    return 0;
  const Eigen::Vector2d t = (b - a) / length, n(t.y(), -t.x());
  // A slab two particle spacings wide: a lattice aligned with the section has exactly two
  // of its columns inside, whatever its offset, so a uniform stream gives U L exactly.
  const double half = fluid.parameters().particle_spacing;
  const auto& p = fluid.particles();
  double flux = 0;
  for (std::size_t i = p.n_boundary; i < p.size(); ++i)
  {
    const Eigen::Vector2d r(p.position[0][i] - a.x(), p.position[1][i] - a.y());
    const double along = r.dot(t), across = r.dot(n);
    if (along < 0 || along > length || std::abs(across) >= half || p.is_ghost(i))
      continue;
    const Eigen::Vector2d v(p.velocity[0][i], p.velocity[1][i]);
    flux += fluid.particle_mass() / p.density[i] * v.dot(n);
  }
  reduce_sums(fluid, &flux, 1);
  return flux / (2 * half);
}

double sample_flow_rate(const FluidSolver<3>& fluid, const Eigen::Vector3d& point,
                        const Eigen::Vector3d& normal)
{
  const double half = fluid.parameters().particle_spacing;
  const auto& p = fluid.particles();
  double flux = 0;
  for (std::size_t i = p.n_boundary; i < p.size(); ++i)
  {
    const Eigen::Vector3d r(p.position[0][i] - point.x(), p.position[1][i] - point.y(),
                            p.position[2][i] - point.z());
    if (std::abs(r.dot(normal)) >= half || p.is_ghost(i))
      continue;
    const Eigen::Vector3d v(p.velocity[0][i], p.velocity[1][i], p.velocity[2][i]);
    flux += fluid.particle_mass() / p.density[i] * v.dot(normal);
  }
  reduce_sums(fluid, &flux, 1);
  return flux / (2 * half);
}

template double sample_pressure(const FluidSolver<2>&, const Eigen::Matrix<double, 2, 1>&);
template double sample_pressure(const FluidSolver<3>&, const Eigen::Matrix<double, 3, 1>&);
template double sample_water_height(const FluidSolver<2>&, const Eigen::Matrix<double, 2, 1>&);
template double sample_water_height(const FluidSolver<3>&, const Eigen::Matrix<double, 3, 1>&);
} // namespace chipflex::sph
