#include "sph/case_setup.h"

#include "common/input_error.h"
#include "sph/tait_equation_of_state.h"

#include <Eigen/Geometry>
#include <cmath>
#include <sstream>
#include <unistd.h>

namespace chipflex::sph
{
template <int dim>
int vertical_axis(const Eigen::Matrix<double, dim, 1>& gravity)
{
  if (gravity.norm() == 0)
    return dim - 1;
  int axis = 0;
  gravity.cwiseAbs().maxCoeff(&axis);
  return axis;
}

template <int dim>
WallSurface<dim> tank_walls(const TankDescription<dim>& tank)
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  WallSurface<dim> w;
  w.name = "tank";
  w.model = tank.model;
  w.lennard_jones = tank.lennard_jones;
  w.dummy_layers = tank.layers;
  const Vector& a = tank.min;
  const Vector& b = tank.max;
  if constexpr (dim == 2)
  {
    // Clockwise, so that the normal (dy, -dx) points into the tank.
    w.vertices = {Vector(b[0], b[1]), Vector(b[0], a[1]), Vector(a[0], a[1]), Vector(a[0], b[1])};
    w.faces = {{0, 1}, {1, 2}, {2, 3}};
    if (!tank.open_top)
      w.faces.push_back({3, 0});
  }
  else
  {
    for (int k = 0; k < 8; ++k)
      w.vertices.push_back(Vector(k & 1 ? b[0] : a[0], k & 2 ? b[1] : a[1], k & 4 ? b[2] : a[2]));
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side)
      {
        if (axis == 2 && side == 1 && tank.open_top)
          continue;
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        auto corner = [&](int i, int j) { return (side << axis) | (i << u) | (j << v); };
        std::array<int, 4> q = {corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
        const Vector n =
            (w.vertices[q[1]] - w.vertices[q[0]]).cross(w.vertices[q[2]] - w.vertices[q[0]]);
        const double inward = side == 0 ? 1 : -1;
        if (n[axis] * inward < 0)
          std::swap(q[1], q[3]);
        w.faces.push_back({q[0], q[1], q[2]});
        w.faces.push_back({q[0], q[2], q[3]});
      }
  }
  return w;
}

namespace
{
/// Lattice points min + (k + 1/2) dp inside [lo, hi].
template <int dim, typename Keep>
void lattice(const Eigen::Matrix<double, dim, 1>& lo, const Eigen::Matrix<double, dim, 1>& hi,
             const Eigen::Matrix<double, dim, 1>& origin, double dp, Keep&& keep)
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  std::array<long, dim> k0, k1;
  for (int d = 0; d < dim; ++d)
  {
    k0[d] = long(std::ceil((lo[d] - origin[d]) / dp - 0.5 - 1e-9));
    k1[d] = long(std::floor((hi[d] - origin[d]) / dp - 0.5 + 1e-9));
  }
  std::array<long, dim> k = k0;
  while (true)
  {
    Vector x;
    for (int d = 0; d < dim; ++d)
      x[d] = origin[d] + (k[d] + 0.5) * dp;
    keep(x);
    int d = 0;
    while (d < dim && ++k[d] > k1[d])
      k[d] = k0[d], ++d;
    if (d == dim)
      break;
    if (k0[d] > k1[d])
      break;
  }
}
} // namespace

/// Refuses, before anything is allocated, a spacing that would need more particles than
/// the ids hold or more memory than the machine has (a typo such as dp = 1e-9 in a 1 m
/// box would otherwise fill the memory for minutes and then fail).
template <int dim>
void check_particle_budget(const CaseDescription<dim>& c)
{
  const double dp = c.fluid.particle_spacing;
  double n = 0;
  for (const auto& b : c.fluid_blocks)
  {
    double cells = 1;
    for (int d = 0; d < dim; ++d)
      cells *= (b.max[d] - b.min[d]) / dp;
    n += cells;
  }
  // State, previous state and force-pass arrays (sph/particle_arrays.h), the sort
  // buffers and the set-up copies: about 200 bytes per particle in 3D.
  const double bytes_per_particle = dim == 3 ? 200 : 150;
  const double bytes = n * bytes_per_particle;
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  const double memory = pages > 0 && page_size > 0 ? double(pages) * double(page_size) : 0;
  if (n > 4e9 || (memory > 0 && bytes > memory))
  {
    std::ostringstream s;
    s.precision(3);
    s << dp << " m gives " << n << " fluid particles, about " << bytes / 1e9
      << " GB (this machine has " << memory / 1e9 << " GB"
      << (n > 4e9 ? "; particle ids hold 4e9" : "") << "): use a coarser spacing";
    throw InputError("fluid/particle spacing", s.str());
  }
}

template <int dim>
std::unique_ptr<FluidSolver<dim>> build_fluid(CaseDescription<dim>& c)
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  auto& p = c.fluid;
  const double dp = p.particle_spacing;
  const int up = vertical_axis<dim>(p.gravity);
  if (!(dp > 0))
    throw InputError("fluid/particle spacing", "must be positive");
  if (c.fluid_blocks.empty())
    throw InputError("geometry/fluid blocks", "the case has no fluid");

  double height = 0;
  for (const auto& b : c.fluid_blocks)
  {
    if (!((b.max - b.min).minCoeff() >= dp))
      throw InputError("geometry/fluid blocks", "a block must be at least one spacing wide");
    height = std::max(height, b.max[up] - b.min[up]);
  }
  check_particle_budget(c);
  if (p.speed_of_sound == 0)
  {
    const double g = p.gravity.norm();
    if (g == 0)
      throw InputError("fluid/speed of sound", "must be given when there is no gravity");
    p.speed_of_sound = c.sound_coefficient * std::sqrt(g * height);
  }

  // Fluid on the lattice anchored at the tank corner (or the block corner), so that
  // tank dummy particles and fluid share one lattice.
  std::vector<Vector> fluid_x;
  std::vector<double> fluid_rho;
  const TaitEquationOfState eos(p.reference_density, p.speed_of_sound, p.gamma);
  for (const auto& b : c.fluid_blocks)
  {
    const Vector origin = c.tank.enabled ? c.tank.min : b.min;
    lattice<dim>(b.min, b.max, origin, dp,
                 [&](const Vector& x)
                 {
                   fluid_x.push_back(x);
                   const double depth = b.max[up] - x[up];
                   fluid_rho.push_back(c.hydrostatic_start ? eos.density(p.reference_density *
                                                                         p.gravity.norm() * depth)
                                                           : p.reference_density);
                 });
  }

  std::vector<WallSurface<dim>> walls = c.walls;
  std::vector<Vector> tank_dummies;
  std::vector<double> tank_rho;
  if (c.tank.enabled)
  {
    walls.insert(walls.begin(), tank_walls(c.tank));
    if (c.tank.model == WallModel::dummy_particles)
    {
      const int layers =
          c.tank.layers > 0 ? c.tank.layers : int(std::ceil(2 * p.smoothing_length() / dp));
      Vector lo = c.tank.min.array() - layers * dp, hi = c.tank.max.array() + layers * dp;
      if (c.tank.open_top)
        hi[up] = c.tank.max[up];
      lattice<dim>(lo, hi, c.tank.min, dp,
                   [&](const Vector& x)
                   {
                     bool inside = true;
                     for (int d = 0; d < dim; ++d)
                       inside = inside && x[d] > c.tank.min[d] && x[d] < c.tank.max[d];
                     if (!inside)
                     {
                       tank_dummies.push_back(x);
                       // Walls start in hydrostatic balance with the fluid beside them (a wall at
                       // rho0 would let the column drop into it and start a pressure wave).
                       double depth = 0;
                       for (const auto& b : c.fluid_blocks)
                         depth = std::max(depth, b.max[up] - x[up]);
                       tank_rho.push_back(
                           c.hydrostatic_start
                               ? eos.density(p.reference_density * p.gravity.norm() * depth)
                               : p.reference_density);
                     }
                   });
    }
  }

  if (c.automatic_domain)
  {
    Vector lo = fluid_x.front(), hi = lo;
    for (const auto& x : fluid_x)
      lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    for (const auto& w : walls)
      for (const auto& x : w.vertices)
        lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    for (const auto& x : tank_dummies)
      lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    const double pad = 0.25 * (hi - lo).maxCoeff() + 4 * p.smoothing_length();
    p.domain_min = lo.array() - pad;
    p.domain_max = hi.array() + pad;
  }

  auto solver = std::make_unique<FluidSolver<dim>>(p);
  for (std::size_t w = 0; w < walls.size(); ++w)
  {
    const bool tank = c.tank.enabled && w == 0;
    solver->add_wall(walls[w], tank ? tank_dummies : std::vector<Vector>{},
                     tank ? tank_rho : std::vector<double>{});
  }
  solver->add_fluid_particles(fluid_x, fluid_rho);
  return solver;
}

template int vertical_axis<2>(const Eigen::Matrix<double, 2, 1>&);
template int vertical_axis<3>(const Eigen::Matrix<double, 3, 1>&);
template WallSurface<2> tank_walls(const TankDescription<2>&);
template WallSurface<3> tank_walls(const TankDescription<3>&);
template std::unique_ptr<FluidSolver<2>> build_fluid(CaseDescription<2>&);
template std::unique_ptr<FluidSolver<3>> build_fluid(CaseDescription<3>&);
} // namespace chipflex::sph
