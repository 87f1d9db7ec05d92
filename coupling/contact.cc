#include "coupling/contact.h"

#include "common/input_error.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace chipflex::coupling
{
void check(const ContactParameters& p, const std::string& where)
{
  auto fail = [&](const std::string& key, const std::string& problem, double value)
  {
    std::ostringstream got;
    got << value;
    throw InputError(where + "/" + key, problem + ", got " + got.str());
  };
  if (!(p.restitution > 0 && p.restitution <= 1))
    fail("restitution", "must lie in (0, 1]", p.restitution);
  if (!(p.friction >= 0))
    fail("friction coefficient", "must be >= 0", p.friction);
  if (!(p.stiffness >= 0))
    fail("stiffness", "must be >= 0 (0: derived)", p.stiffness);
  if (!(p.steps >= 4))
    fail("steps per contact", "must be >= 4 (the contact must be resolved in time)", p.steps);
  if (!(p.tangential_ratio > 0))
    fail("tangential stiffness ratio", "must be positive", p.tangential_ratio);
  if (!(p.thickness >= 0))
    fail("thickness", "must be >= 0 (0: derived)", p.thickness);
}

double damping_ratio(double e)
{
  const double l = std::log(e);
  return -l / std::sqrt(M_PI * M_PI + l * l);
}

namespace
{
constexpr double inside_tolerance = 1e-9; ///< on the barycentric weights
constexpr long max_cells_per_face = 4096; ///< larger faces are tested against every node

template <int dim>
struct Projection
{
  Eigen::Matrix<double, dim, 1> normal = Eigen::Matrix<double, dim, 1>::Zero();
  double distance = 0;               ///< signed, positive on the normal side
  double clamped_distance = 0;       ///< to the closed face
  std::array<double, dim> weights{}; ///< of the foot point on the plane
  bool inside = false;
};

/// Signed distance to the face's plane, barycentric weights of the foot point, and the
/// distance to the closed face (to pick the closest face near edges and corners).
template <int dim>
Projection<dim> project(const std::array<const Eigen::Matrix<double, dim, 1>*, dim>& v,
                        const Eigen::Matrix<double, dim, 1>& x)
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  Projection<dim> p;
  const Vector& a = *v[0];
  if constexpr (dim == 2)
  {
    const Vector e = *v[1] - a;
    const double l2 = e.squaredNorm();
    p.normal = Vector(e[1], -e[0]) / std::sqrt(l2);
    const double t = (x - a).dot(e) / l2;
    p.weights = {1 - t, t};
    p.distance = (x - a).dot(p.normal);
    p.inside = t >= -inside_tolerance && t <= 1 + inside_tolerance;
    const double tc = std::clamp(t, 0.0, 1.0);
    p.clamped_distance = (x - (a + tc * e)).norm();
  }
  else
  {
    const Vector e1 = *v[1] - a, e2 = *v[2] - a;
    p.normal = e1.cross(e2).normalized();
    const Vector w = x - a;
    const double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2);
    const double w1 = w.dot(e1), w2 = w.dot(e2);
    const double den = d11 * d22 - d12 * d12;
    const double u = (d22 * w1 - d12 * w2) / den, s = (d11 * w2 - d12 * w1) / den;
    p.weights = {1 - u - s, u, s};
    p.distance = w.dot(p.normal);
    p.inside = u >= -inside_tolerance && s >= -inside_tolerance && u + s <= 1 + inside_tolerance;
    if (u >= 0 && s >= 0 && u + s <= 1)
      p.clamped_distance = std::abs(p.distance);
    else
    {
      // Outside the triangle: the closest point lies on one of its edges.
      auto segment = [&](const Vector& p0, const Vector& p1)
      {
        const Vector e = p1 - p0;
        const double t = std::clamp((x - p0).dot(e) / e.squaredNorm(), 0.0, 1.0);
        return (x - (p0 + t * e)).norm();
      };
      p.clamped_distance = std::min({segment(a, *v[1]), segment(*v[1], *v[2]), segment(*v[2], a)});
    }
  }
  return p;
}
} // namespace

template <int dim>
ContactModel<dim>::ContactModel(const ContactParameters& parameters) : parameters_(parameters)
{
  check(parameters_, "contact");
}

template <int dim>
int ContactModel<dim>::add_obstacle(const sph::WallSurface<dim>& wall)
{
  if (set_up_)
    throw std::logic_error("ContactModel::add_obstacle after the first compute()");
  obstacles_.push_back({&wall, {}});
  return int(obstacles_.size()) - 1;
}

template <int dim>
int ContactModel<dim>::add_body(const mbs::SkinBody<dim>& skin, double mass,
                                const std::string& name, std::function<double(double)> lead)
{
  if (set_up_)
    throw std::logic_error("ContactModel::add_body after the first compute()");
  if (!(mass > 0))
    throw InputError("contact, body '" + name + "'",
                     "needs a positive mass, got " + std::to_string(mass));
  Body b;
  b.skin = &skin;
  b.mass = mass;
  b.name = name;
  b.lead = std::move(lead);
  bodies_.push_back(std::move(b));
  return int(bodies_.size()) - 1;
}

template <int dim>
int ContactModel<dim>::n_faces(int s) const
{
  const int no = n_obstacles();
  return s < no ? int(obstacles_[s].wall->faces.size())
                : int(bodies_[s - no].skin->skin_faces().size());
}

template <int dim>
const std::array<int, dim>& ContactModel<dim>::face(int s, int f) const
{
  const int no = n_obstacles();
  return s < no ? obstacles_[s].wall->faces[f] : bodies_[s - no].skin->skin_faces()[f];
}

template <int dim>
const typename ContactModel<dim>::Vector& ContactModel<dim>::vertex(int s, int v) const
{
  const int no = n_obstacles();
  return s < no ? obstacle_x_[s][v] : bodies_[s - no].xp[v];
}

template <int dim>
const typename ContactModel<dim>::Vector& ContactModel<dim>::vertex_velocity(int s, int v) const
{
  const int no = n_obstacles();
  return s < no ? obstacle_v_[s][v] : bodies_[s - no].v[v];
}

template <int dim>
double ContactModel<dim>::pair_mass(int b, int partner) const
{
  const double m = bodies_[b].mass;
  if (partner < n_obstacles())
    return m;
  const double mc = bodies_[partner - n_obstacles()].mass;
  return m * mc / (m + mc);
}

template <int dim>
double ContactModel<dim>::pair_stiffness(int b, int partner) const
{
  if (parameters_.stiffness > 0)
    return parameters_.stiffness;
  std::size_t n = bodies_[b].skin->n_skin_nodes();
  if (partner >= n_obstacles())
    n = std::max(n, bodies_[partner - n_obstacles()].skin->n_skin_nodes());
  const double omega = M_PI / (parameters_.steps * reference_dt_);
  return pair_mass(b, partner) / double(n) * omega * omega;
}

template <int dim>
double ContactModel<dim>::stiffness_with_obstacle(int b, int o) const
{
  return pair_stiffness(b, o);
}

template <int dim>
double ContactModel<dim>::stiffness_with_body(int b, int c) const
{
  return pair_stiffness(b, n_obstacles() + c);
}

template <int dim>
void ContactModel<dim>::setup(double dt)
{
  if (reference_dt_ <= 0)
    reference_dt_ = dt;
  // Mean skin-edge length of each body: half the shortest is the default thickness, the
  // longest the grid cell (a node then meets the faces of a few cells' worth of skin).
  double shortest = std::numeric_limits<double>::infinity(), longest = 0;
  for (auto& b : bodies_)
  {
    b.skin->skin_positions(b.x);
    double sum = 0;
    int count = 0;
    for (const auto& f : b.skin->skin_faces())
      for (int k = 0; k < dim; ++k)
      {
        sum += (b.x[f[(k + 1) % dim]] - b.x[f[k]]).norm();
        ++count;
      }
    if (count == 0)
      continue;
    shortest = std::min(shortest, sum / count);
    longest = std::max(longest, sum / count);
  }
  if (thickness_ <= 0)
    thickness_ = parameters_.thickness > 0 ? parameters_.thickness
                 : std::isfinite(shortest) ? 0.5 * shortest
                                           : 0;
  if (cell_ <= 0)
    cell_ = std::max(longest, 2 * thickness_);
  set_up_ = true;
}

template <int dim>
std::uint64_t ContactModel<dim>::cell_key(const Vector& x) const
{
  std::uint64_t key = 0;
  for (int d = 0; d < dim; ++d)
  {
    const auto c = static_cast<std::int64_t>(std::floor(x[d] / cell_));
    key = key * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(c) * 0xBF58476D1CE4E5B9ull;
  }
  return key;
}

template <int dim>
void ContactModel<dim>::bin_faces()
{
  const int no = n_obstacles(), ns = no + n_bodies();
  // The obstacles (walls, barriers: many faces, most of them at rest) are binned with a
  // slack and kept while no vertex has moved by more than it; the bodies every step.
  // A face whose box, widened by the thickness (and the slack), covers a node's cell is
  // a candidate: every face within the thickness of the node is one either way.
  const double slack = 0.5 * cell_;
  bool moved = binned_obstacle_x_.size() != std::size_t(no);
  for (int o = 0; o < no && !moved; ++o)
  {
    moved = binned_obstacle_x_[o].size() != obstacle_x_[o].size();
    for (std::size_t k = 0; k < obstacle_x_[o].size() && !moved; ++k)
      moved = (obstacle_x_[o][k] - binned_obstacle_x_[o][k]).squaredNorm() > slack * slack;
  }
  if (moved)
  {
    obstacle_grid_.clear();
    obstacle_large_faces_.clear();
    for (int o = 0; o < no; ++o)
      bin_surface(o, thickness_ + slack, obstacle_grid_, obstacle_large_faces_);
    binned_obstacle_x_ = obstacle_x_;
  }
  // Keep the buckets' memory from step to step, but forget cells the bodies have left:
  // clear when most cells went unused.
  if (grid_.size() > 2 * used_cells_ + 1024)
    grid_.clear();
  for (auto& [key, list] : grid_)
    list.clear();
  large_faces_.clear();
  used_cells_ = 0;
  for (int s = no; s < ns; ++s)
    if (bodies_[s - no].active)
      used_cells_ += bin_surface(s, thickness_, grid_, large_faces_);
}

template <int dim>
std::size_t ContactModel<dim>::bin_surface(int s, double widen, Grid& grid,
                                           std::vector<std::pair<int, int>>& large) const
{
  std::size_t filled = 0;
  for (int f = 0; f < n_faces(s); ++f)
  {
    const auto& fc = face(s, f);
    Vector lo = vertex(s, fc[0]), hi = lo;
    for (int k = 1; k < dim; ++k)
    {
      lo = lo.cwiseMin(vertex(s, fc[k]));
      hi = hi.cwiseMax(vertex(s, fc[k]));
    }
    if (!lo.allFinite() || !hi.allFinite())
      continue;
    lo.array() -= widen;
    hi.array() += widen;
    std::array<long, dim> c0, c1;
    double cells = 1; // double: a huge face must not overflow the count
    for (int d = 0; d < dim; ++d)
    {
      c0[d] = long(std::floor(lo[d] / cell_));
      c1[d] = long(std::floor(hi[d] / cell_));
      cells *= double(c1[d] - c0[d] + 1);
    }
    if (cells > double(max_cells_per_face))
    {
      large.emplace_back(s, f);
      continue;
    }
    std::array<long, dim> c = c0;
    while (true)
    {
      Vector centre;
      for (int d = 0; d < dim; ++d)
        centre[d] = (c[d] + 0.5) * cell_;
      auto& list = grid[cell_key(centre)];
      filled += list.empty();
      list.emplace_back(s, f);
      int d = 0;
      for (; d < dim; ++d)
      {
        if (++c[d] <= c1[d])
          break;
        c[d] = c0[d];
      }
      if (d == dim)
        break;
    }
  }
  return filled;
}

template <int dim>
void ContactModel<dim>::detect()
{
  contacts_.clear();
  const int no = n_obstacles(), ns = no + n_bodies();
  struct Best
  {
    double clamped = std::numeric_limits<double>::infinity();
    int face = -1;
    Projection<dim> p;
  };
  std::vector<Best> best(ns);
  std::vector<int> touched;
  // Node i of surface `owner` against the faces near it: every other body's, and the
  // obstacles' for a body node.
  auto test_node = [&](int owner, int i, const Vector& x)
  {
    if (!x.allFinite()) // a body gone non-finite: the run stops on it, not here
      return;
    touched.clear();
    auto consider = [&](int s, int f)
    {
      if (s == owner || (owner < no && s < no))
        return;
      const auto& fc = face(s, f);
      std::array<const Vector*, dim> v;
      for (int k = 0; k < dim; ++k)
        v[k] = &vertex(s, fc[k]);
      const auto p = project<dim>(v, x);
      if (p.clamped_distance > thickness_)
        return;
      Best& bs = best[s];
      if (bs.face < 0)
        touched.push_back(s);
      // The closest face decides; at a shared edge or vertex (equal distances) the
      // face the node lies most clearly in front of or behind.
      const double tie = 1e-12 * cell_;
      if (bs.face < 0 || p.clamped_distance < bs.clamped - tie ||
          (p.clamped_distance <= bs.clamped + tie &&
           std::abs(p.distance) > std::abs(bs.p.distance)))
      {
        bs.clamped = p.clamped_distance;
        bs.face = f;
        bs.p = p;
      }
    };
    const auto key = cell_key(x);
    for (const Grid* grid : {&obstacle_grid_, &grid_})
    {
      const auto it = grid->find(key);
      if (it != grid->end())
        for (const auto& [s, f] : it->second)
          consider(s, f);
    }
    for (const auto* large : {&obstacle_large_faces_, &large_faces_})
      for (const auto& [s, f] : *large)
        consider(s, f);
    std::sort(touched.begin(), touched.end()); // a fixed order whatever the hashing
    for (int s : touched)
    {
      Best& bs = best[s];
      if (bs.p.inside && bs.p.distance < 0 && -bs.p.distance <= thickness_)
        contacts_.push_back({owner, i, s, bs.face, bs.p.weights, bs.p.normal, -bs.p.distance});
      bs = Best();
    }
  };
  for (int b = 0; b < n_bodies(); ++b)
    for (int i = 0; bodies_[b].active && i < int(bodies_[b].xp.size()); ++i)
      test_node(no + b, i, bodies_[b].xp[i]);
  // The obstacles' vertices against the bodies' faces: a wall's corner or a barrier's
  // end that pokes into a body between its nodes.
  if (n_bodies() > 0)
    for (int o = 0; o < no; ++o)
      for (int i = 0; i < int(obstacle_x_[o].size()); ++i)
        test_node(o, i, obstacle_x_[o][i]);
}

template <int dim>
void ContactModel<dim>::compute(double dt)
{
  if (!(dt > 0))
    throw std::invalid_argument("ContactModel::compute: dt must be positive");
  if (!set_up_)
    setup(dt);
  const int no = n_obstacles();
  // Positions a little ahead: the obstacles (prescribed motion) half a step, each body
  // by the lead of its integrator.
  obstacle_x_.resize(no);
  obstacle_v_.resize(no);
  for (int o = 0; o < no; ++o)
  {
    const auto& w = *obstacles_[o].wall;
    obstacle_x_[o] = w.vertices;
    if (w.velocities.size() == w.vertices.size())
      obstacle_v_[o] = w.velocities;
    else // a wall given without velocities is at rest
      obstacle_v_[o].assign(w.vertices.size(), Vector::Zero());
    for (std::size_t k = 0; k < w.vertices.size(); ++k)
      obstacle_x_[o][k] += 0.5 * dt * obstacle_v_[o][k];
    obstacles_[o].force.assign(w.vertices.size(), Vector::Zero());
  }
  for (auto& b : bodies_)
  {
    b.skin->skin_positions(b.x);
    b.skin->skin_velocities(b.v);
    b.xp.resize(b.x.size());
    const double lead = b.lead ? b.lead(dt) : 0.5;
    for (std::size_t k = 0; k < b.x.size(); ++k)
      b.xp[k] = b.x[k] + lead * dt * b.v[k];
    b.force.assign(b.x.size(), Vector::Zero());
  }
  contacts_.clear();
  n_contacts_ = 0;
  max_overlap_ = 0;
  if (!(cell_ > 0 && thickness_ > 0)) // no body with a skin: nothing can touch
  {
    tangential_.clear();
    return;
  }
  bin_faces();
  detect();

  // Contacts per (body, partner): they share the pair's reduced mass in the damping.
  const int ns = no + n_bodies();
  std::vector<int> count(ns * ns, 0);
  for (const auto& c : contacts_)
    ++count[c.owner * ns + c.partner];

  const double zeta = damping_ratio(parameters_.restitution);
  const double mu = parameters_.friction;
  std::map<std::tuple<int, int, int>, Vector> tangential;
  max_overlap_ = 0;
  for (const auto& c : contacts_)
  {
    // The pair as (body, other surface): a body's node, or an obstacle's vertex on a body.
    const int body = c.owner < no ? c.partner - no : c.owner - no;
    const int other = c.owner < no ? c.owner : c.partner;
    const double m = pair_mass(body, other) / count[c.owner * ns + c.partner];
    const double k = pair_stiffness(body, other);
    const double damping = 2 * zeta * std::sqrt(k * m);
    const auto& fc = face(c.partner, c.face);
    Vector v_face = Vector::Zero();
    for (int j = 0; j < dim; ++j)
      v_face += c.weights[j] * vertex_velocity(c.partner, fc[j]);
    const Vector v_rel = vertex_velocity(c.owner, c.node) - v_face;
    const double vn = v_rel.dot(c.normal);
    const double fn = k * c.overlap - damping * vn;
    Vector f = fn * c.normal;
    if (mu > 0)
    {
      const auto key = std::make_tuple(c.owner, c.node, c.partner);
      Vector xi = Vector::Zero();
      if (const auto it = tangential_.find(key); it != tangential_.end())
      {
        // Keep the spring's length, turned into the current tangent plane.
        xi = it->second;
        const double len = xi.norm();
        xi -= xi.dot(c.normal) * c.normal;
        if (xi.norm() > 0)
          xi *= len / xi.norm();
      }
      const Vector vt = v_rel - vn * c.normal;
      xi += dt * vt;
      const double kt = parameters_.tangential_ratio * k;
      const double ct = 2 * zeta * std::sqrt(kt * m);
      Vector ft = -kt * xi - ct * vt;
      const double limit = mu * std::max(fn, 0.0);
      if (ft.norm() > limit)
      {
        ft = ft.norm() > 0 ? Vector(ft * (limit / ft.norm())) : Vector::Zero();
        xi = -(ft + ct * vt) / kt;
      }
      f += ft;
      tangential[key] = xi;
    }
    (c.owner < no ? obstacles_[c.owner].force : bodies_[c.owner - no].force)[c.node] += f;
    auto& reaction = c.partner < no ? obstacles_[c.partner].force : bodies_[c.partner - no].force;
    for (int j = 0; j < dim; ++j)
      reaction[fc[j]] -= c.weights[j] * f;
    max_overlap_ = std::max(max_overlap_, c.overlap);
  }
  tangential_ = std::move(tangential);
  n_contacts_ = int(contacts_.size());
}

template <int dim>
std::vector<double> ContactModel<dim>::state() const
{
  std::vector<double> s = {reference_dt_, thickness_, cell_, double(tangential_.size())};
  for (const auto& [key, xi] : tangential_)
  {
    s.push_back(std::get<0>(key));
    s.push_back(std::get<1>(key));
    s.push_back(std::get<2>(key));
    for (int d = 0; d < dim; ++d)
      s.push_back(xi[d]);
  }
  return s;
}

template <int dim>
void ContactModel<dim>::restore(const std::vector<double>& s)
{
  if (s.size() < 4 || s.size() != 4 + std::size_t(s[3]) * (3 + dim))
    throw InputError("checkpoint", "the contact state has the wrong size");
  reference_dt_ = s[0];
  thickness_ = s[1];
  cell_ = s[2];
  tangential_.clear();
  for (std::size_t e = 0, at = 4; e < std::size_t(s[3]); ++e, at += 3 + dim)
  {
    Vector xi;
    for (int d = 0; d < dim; ++d)
      xi[d] = s[at + 3 + d];
    tangential_[std::make_tuple(int(s[at]), int(s[at + 1]), int(s[at + 2]))] = xi;
  }
  set_up_ = reference_dt_ > 0;
}

template class ContactModel<2>;
template class ContactModel<3>;
} // namespace chipflex::coupling
