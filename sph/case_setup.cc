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
    // Faces: right (x), floor (y), left (x), lid (y).
    if (tank.open_axis != 0)
      w.faces.push_back({0, 1});
    if (tank.open_axis != 1)
      w.faces.push_back({1, 2});
    if (tank.open_axis != 0)
      w.faces.push_back({2, 3});
    if (!tank.open_top && tank.open_axis != 1)
      w.faces.push_back({3, 0});
  }
  else
  {
    for (int k = 0; k < 8; ++k)
      w.vertices.push_back(Vector(k & 1 ? b[0] : a[0], k & 2 ? b[1] : a[1], k & 4 ? b[2] : a[2]));
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side)
      {
        if ((axis == 2 && side == 1 && tank.open_top) || axis == tank.open_axis)
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
  // Inlets: what they create over the run. Ids must hold all of it; memory only when no
  // outlet takes it out again (otherwise the fluid in the domain stays what it was).
  double inflow = 0;
  bool outlet = false;
  for (const auto& z : c.open_boundaries)
  {
    double buffer = 1;
    for (int d = 0; d < dim; ++d)
      buffer *= (z.box_max[d] - z.box_min[d]) / dp;
    n += buffer;
    outlet = outlet || z.kind == OpenBoundaryKind::outlet;
    if (z.kind == OpenBoundaryKind::inlet)
      inflow += z.velocity * z.section_area() * c.end_time / std::pow(dp, dim);
  }
  const double ever = n + inflow;
  if (!outlet)
    n += inflow;
  // State, previous state and force-pass arrays (sph/particle_arrays.h), the sort
  // buffers and the set-up copies: about 200 bytes per particle in 3D.
  const double bytes_per_particle = dim == 3 ? 200 : 150;
  const double bytes = n * bytes_per_particle;
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  const double memory = pages > 0 && page_size > 0 ? double(pages) * double(page_size) : 0;
  if (ever > 4e9 || (memory > 0 && bytes > memory))
  {
    std::ostringstream s;
    s.precision(3);
    s << dp << " m gives " << n << " fluid particles, about " << bytes / 1e9
      << " GB (this machine has " << memory / 1e9 << " GB"
      << (ever > 4e9
              ? "; " + std::to_string(ever) + " over the run with the inflow, particle ids hold 4e9"
              : "")
      << "): use a coarser spacing";
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
  std::vector<Vector> fluid_x, fluid_v;
  std::vector<double> fluid_rho;
  const TaitEquationOfState eos(p.reference_density, p.speed_of_sound, p.gamma);
  const auto in_buffer = [&](const Vector& x)
  {
    for (const auto& z : c.open_boundaries)
      if (z.in_section(x.data()) && z.depth(x.data()) > 0 && z.depth(x.data()) <= z.thickness())
        return true;
    return false;
  };
  double top = -1e300;
  for (const auto& b : c.fluid_blocks)
    top = std::max(top, b.max[up]);
  for (const auto& b : c.fluid_blocks)
  {
    const Vector origin = c.tank.enabled ? c.tank.min : b.min;
    lattice<dim>(b.min, b.max, origin, dp,
                 [&](const Vector& x)
                 {
                   if (in_buffer(x) || (c.fluid_region && !c.fluid_region(x)))
                     return;
                   fluid_x.push_back(x);
                   fluid_v.push_back(c.initial_velocity);
                   const double depth = b.max[up] - x[up];
                   fluid_rho.push_back(c.hydrostatic_start ? eos.density(p.reference_density *
                                                                         p.gravity.norm() * depth)
                                                           : p.reference_density);
                 });
  }
  // The buffers, on the same lattice: the fluid's rows continue through the planes.
  std::vector<OpenBoundary<dim>> zones = c.open_boundaries;
  for (auto& z : zones)
  {
    const Vector origin = c.tank.enabled ? c.tank.min : z.box_min;
    const double offset = (z.plane() - origin[z.axis]) / dp;
    if (std::abs(offset - std::round(offset)) > 1e-6 * std::max(1.0, std::abs(offset)))
      throw InputError("open boundaries/" + z.name,
                       "the plane must lie a whole number of particle spacings from the "
                       "lattice origin (the tank's min corner)");
    if (z.kind == OpenBoundaryKind::inlet && z.flow_rate > 0 && z.profile == InletProfile::uniform)
    {
      std::size_t filled = 0;
      lattice<dim>(z.box_min, z.box_max, origin, dp,
                   [&](const Vector& x) { filled += !c.fluid_region || c.fluid_region(x); });
      if (filled == 0)
        throw InputError("open boundaries/" + z.name, "no fluid fills the buffer's box");
      z.velocity = z.flow_rate * z.thickness() / (double(filled) * std::pow(dp, dim));
    }
    lattice<dim>(z.box_min, z.box_max, origin, dp,
                 [&](const Vector& x)
                 {
                   if (c.fluid_region && !c.fluid_region(x))
                     return;
                   fluid_x.push_back(x);
                   Vector v = c.initial_velocity;
                   if (z.kind == OpenBoundaryKind::inlet)
                   {
                     v.setZero();
                     v[z.axis] = z.sign * z.speed(x.data(), 0);
                   }
                   fluid_v.push_back(v);
                   const double depth = std::max(0.0, top - x[up]);
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
      if (c.tank.open_axis >= 0)
        lo[c.tank.open_axis] = c.tank.min[c.tank.open_axis],
        hi[c.tank.open_axis] = c.tank.max[c.tank.open_axis];
      lattice<dim>(
          lo, hi, c.tank.min, dp,
          [&](const Vector& x)
          {
            bool inside = true;
            for (int d = 0; d < dim; ++d)
              inside = inside &&
                       (d == c.tank.open_axis || (x[d] > c.tank.min[d] && x[d] < c.tank.max[d]));
            if (!inside)
            {
              tank_dummies.push_back(x);
              // Walls start in hydrostatic balance with the fluid beside them (a wall at
              // rho0 would let the column drop into it and start a pressure wave).
              double depth = 0;
              for (const auto& b : c.fluid_blocks)
                depth = std::max(depth, b.max[up] - x[up]);
              tank_rho.push_back(c.hydrostatic_start
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
  for (const auto& z : zones)
    solver->add_open_boundary(z);
  solver->add_fluid_particles(fluid_x, fluid_rho, fluid_v);
  return solver;
}

template int vertical_axis<2>(const Eigen::Matrix<double, 2, 1>&);
template int vertical_axis<3>(const Eigen::Matrix<double, 3, 1>&);
template WallSurface<2> tank_walls(const TankDescription<2>&);
template WallSurface<3> tank_walls(const TankDescription<3>&);
template std::unique_ptr<FluidSolver<2>> build_fluid(CaseDescription<2>&);
template std::unique_ptr<FluidSolver<3>> build_fluid(CaseDescription<3>&);
} // namespace chipflex::sph
