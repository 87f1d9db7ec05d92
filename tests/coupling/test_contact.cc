// Contact (coupling/contact.h, docs/contact.md) against analytic results, without fluid
// (coupling::ContactSimulation):
//  - a rigid box dropped flat on the floor from h0 bounces to e^2 h0: the linear
//    spring-dashpot with zeta = -ln e / sqrt(pi^2 + ln^2 e) returns the normal velocity
//    times e (Schwager & Poeschel 2007), and a free flight from v turns at v^2 / 2g;
//    2D and 3D (a box of triangles), within 5 %;
//  - a block on an incline (2D, and a 3D box on a floor tilted about a skew axis): with
//    tan(phi) < mu static friction holds it (it does not creep), with tan(phi) > mu it
//    slides with a = g (sin phi - mu cos phi) (Coulomb's law; any textbook of
//    mechanics), within 2 %;
//  - two free flexible bars meet head-on: the contact forces are equal and opposite on
//    node and face (barycentric weights sum to one), so the total linear momentum is
//    conserved to round-off (1e-9 relative), and the damped contact takes energy out
//    (kinetic + strain energy after the impact not above the energy before).

#include "coupling/contact_simulation.h"
#include "coupling/multibody_coupled_body.h"
#include "coupling/rigid_shapes.h"
#include "mbs/rigid_body.h"
#include "truss_beam.h"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>

using namespace chipflex;
using Vector2 = Eigen::Vector2d;
using Vector3 = Eigen::Vector3d;

namespace
{
constexpr double g = 9.81;

/// A 2D segment wall from a to b; bodies are on the right of a -> b (the fluid side).
sph::WallSurface<2> segment_wall(const Vector2& a, const Vector2& b)
{
  sph::WallSurface<2> w;
  w.name = "floor";
  w.vertices = {a, b};
  w.faces = {{0, 1}};
  return w;
}

std::unique_ptr<coupling::CoupledBody<2>> free_box_2d(const Vector2& centre, double angle,
                                                      double width, double height)
{
  // Skin nodes a quarter of the shorter side apart.
  const auto s = coupling::box_shape<2>(Vector2(width, height), 1000, std::min(width, height) / 4);
  auto system = std::make_unique<mbs::MultibodySystem<2>>(mbs::IntegratorOptions{});
  system->set_gravity(Vector2(0, -g));
  auto box = mbs::make_rigid_body<2>(
      mbs::rigid_body_data<2>(s.mass, s.centre_of_mass, s.inertia, s.nodes, s.faces));
  box->set_pose(centre, angle);
  auto* skin = box.get();
  system->add_body(std::move(box));
  return std::make_unique<coupling::MultibodyCoupledBody<2>>("rigid", std::move(system), *skin);
}

/// Drops a 2D box flat from h0 (its bottom above the floor y = 0) and returns the height
/// of its bottom at the top of the first bounce.
double bounce_height_2d(double e, double h0)
{
  const double w = 0.1, h = 0.05;
  auto box = free_box_2d(Vector2(0, h0 + h / 2), 0, w, h);
  coupling::ContactParameters p;
  p.restitution = e;
  p.friction = 0.3;
  coupling::ContactSimulation<2> sim(p);
  sim.add_wall(segment_wall(Vector2(1, 0), Vector2(-1, 0)));
  sim.add_body(*box, "box");
  const double dt = 2e-5;
  bool touched = false;
  double apex = 0;
  for (int step = 0; step < 100000; ++step)
  {
    sim.step(dt);
    const double y = box->probe_position().y() - h / 2;
    if (sim.contact().n_contacts() > 0)
      touched = true;
    else if (touched)
    {
      apex = std::max(apex, y);
      if (box->linear_momentum().y() < 0)
        break;
    }
  }
  REQUIRE(touched);
  return apex;
}

/// A closed box surface of triangles (outward), n x n squares on every side.
void box_skin(const Vector3& size, int n, std::vector<Vector3>& nodes,
              std::vector<std::array<int, 3>>& faces)
{
  std::map<std::array<long, 3>, int> index;
  auto node = [&](const Vector3& x)
  {
    std::array<long, 3> key;
    for (int d = 0; d < 3; ++d)
      key[d] = std::lround(x[d] / size[d] * 2 * n);
    const auto it = index.find(key);
    if (it != index.end())
      return it->second;
    nodes.push_back(x);
    return index[key] = int(nodes.size()) - 1;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side : {-1, 1})
    {
      // (u, v, axis) right-handed, so u x v = +axis; flip for the - side.
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
        {
          auto corner = [&](int a, int b)
          {
            Vector3 x;
            x[axis] = side * size[axis] / 2;
            x[u] = (-0.5 + double(a) / n) * size[u];
            x[v] = (-0.5 + double(b) / n) * size[v];
            return node(x);
          };
          const int c00 = corner(i, j), c10 = corner(i + 1, j), c11 = corner(i + 1, j + 1),
                    c01 = corner(i, j + 1);
          if (side > 0)
          {
            faces.push_back({c00, c10, c11});
            faces.push_back({c00, c11, c01});
          }
          else
          {
            faces.push_back({c00, c11, c10});
            faces.push_back({c00, c01, c11});
          }
        }
    }
}

/// A free rigid box (1000 kg/m^3) with a skin of 3 x 3 squares per side, centre c,
/// rotation r.
std::unique_ptr<coupling::MultibodyCoupledBody<3>> box_3d(const Vector3& size, const Vector3& c,
                                                          const Eigen::Matrix3d& r)
{
  const double density = 1000, m = density * size.prod();
  std::vector<Vector3> nodes;
  std::vector<std::array<int, 3>> faces;
  box_skin(size, 3, nodes, faces);
  // Outward orientation: the enclosed volume (divergence theorem) is the box's.
  double volume = 0;
  for (const auto& f : faces)
    volume += nodes[f[0]].dot(nodes[f[1]].cross(nodes[f[2]])) / 6;
  REQUIRE(volume == Approx(size.prod()).epsilon(1e-12));
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  inertia(0, 0) = m * (size[1] * size[1] + size[2] * size[2]) / 12;
  inertia(1, 1) = m * (size[0] * size[0] + size[2] * size[2]) / 12;
  inertia(2, 2) = m * (size[0] * size[0] + size[1] * size[1]) / 12;
  auto system = std::make_unique<mbs::MultibodySystem<3>>();
  system->set_gravity(Vector3(0, 0, -g));
  auto rigid =
      mbs::make_rigid_body<3>(mbs::rigid_body_data<3>(m, Vector3::Zero(), inertia, nodes, faces));
  rigid->set_pose(c, r);
  auto* skin = rigid.get();
  system->add_body(std::move(rigid));
  return std::make_unique<coupling::MultibodyCoupledBody<3>>("rigid", std::move(system), *skin);
}

/// A 2 x 2 m floor of two triangles through the origin, normal r e_z.
sph::WallSurface<3> floor_3d(const Eigen::Matrix3d& r)
{
  sph::WallSurface<3> floor;
  floor.name = "floor";
  for (const Vector3& x :
       {Vector3(-1, -1, 0), Vector3(1, -1, 0), Vector3(1, 1, 0), Vector3(-1, 1, 0)})
    floor.vertices.push_back(r * x);
  floor.faces = {{0, 1, 2}, {0, 2, 3}}; // normal r e_z
  return floor;
}

double bounce_height_3d(double e, double h0)
{
  const Vector3 size(0.1, 0.08, 0.05);
  auto box_ptr = box_3d(size, Vector3(0, 0, h0 + size[2] / 2), Eigen::Matrix3d::Identity());
  auto& box = *box_ptr;
  const auto floor = floor_3d(Eigen::Matrix3d::Identity());
  coupling::ContactParameters p;
  p.restitution = e;
  coupling::ContactSimulation<3> sim(p);
  sim.add_wall(floor);
  sim.add_body(box, "box");
  const double dt = 2e-5;
  bool touched = false;
  double apex = 0;
  for (int step = 0; step < 100000; ++step)
  {
    sim.step(dt);
    const double z = box.probe_position().z() - size[2] / 2;
    if (sim.contact().n_contacts() > 0)
      touched = true;
    else if (touched)
    {
      apex = std::max(apex, z);
      if (box.linear_momentum().z() < 0)
        break;
    }
  }
  REQUIRE(touched);
  return apex;
}

/// The 3D box resting on a floor tilted by phi about an axis between x and y (so that
/// the slope runs along no face of the grid), measured over 0.05 ... 0.35 s.
double slide_on_incline_3d(double phi, double mu, double& distance)
{
  const Vector3 size(0.1, 0.08, 0.05);
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(phi, Vector3(1, 2, 0).normalized()).toRotationMatrix();
  const Vector3 normal = r * Vector3::UnitZ();
  const Vector3 down = (-Vector3::UnitZ() + normal.z() * normal).normalized();
  auto box = box_3d(size, normal * (size[2] / 2), r);
  coupling::ContactParameters p;
  p.restitution = 0.5;
  p.friction = mu;
  coupling::ContactSimulation<3> sim(p);
  sim.add_wall(floor_3d(r));
  sim.add_body(*box, "box");
  const double dt = 2e-5, t1 = 0.05, t2 = 0.35;
  double s1 = 0, v1 = 0;
  while (sim.time() < t2 - dt / 2)
  {
    sim.step(dt);
    if (std::abs(sim.time() - t1) < dt / 2)
    {
      s1 = box->probe_position().dot(down);
      v1 = box->system().body(0).frame_velocity().dot(down);
    }
  }
  REQUIRE(sim.contact().n_contacts() > 0);
  const double s2 = box->probe_position().dot(down), T = t2 - t1;
  distance = s2 - s1;
  return 2 * (s2 - s1 - v1 * T) / (T * T);
}

struct Slide
{
  double acceleration; ///< down the incline, m/s^2, from the distance travelled
  double distance;     ///< m, over the measuring window
};

/// A box resting on an incline of angle phi (the floor through the origin, rising to
/// the right), measured over 0.05 ... 0.35 s after its release.
Slide slide_on_incline(double phi, double mu)
{
  const double w = 0.1, h = 0.05;
  const Vector2 down(-std::cos(phi), -std::sin(phi)), normal(-std::sin(phi), std::cos(phi));
  auto box = free_box_2d(normal * (h / 2), phi, w, h);
  coupling::ContactParameters p;
  p.restitution = 0.5;
  p.friction = mu;
  coupling::ContactSimulation<2> sim(p);
  sim.add_wall(segment_wall(-2 * down, 2 * down)); // normal: `normal`
  sim.add_body(*box, "box");
  const double dt = 2e-5, t1 = 0.05, t2 = 0.35;
  double s1 = 0, v1 = 0;
  auto* rigid = dynamic_cast<coupling::MultibodyCoupledBody<2>*>(box.get());
  REQUIRE(rigid);
  while (sim.time() < t2 - dt / 2)
  {
    sim.step(dt);
    if (std::abs(sim.time() - t1) < dt / 2)
    {
      s1 = box->probe_position().dot(down);
      v1 = rigid->system().body(0).frame_velocity().dot(down);
    }
  }
  const double s2 = box->probe_position().dot(down), T = t2 - t1;
  REQUIRE(sim.contact().n_contacts() > 0);
  // s2 = s1 + v1 T + a T^2 / 2 at constant acceleration.
  return {2 * (s2 - s1 - v1 * T) / (T * T), s2 - s1};
}

/// The free-free truss strip of tests/mbs/truss_beam.h with its frame moved to the
/// centre of mass, so that p = m R' and the explicit step turns a held load into exactly
/// that impulse (as tests/coupling/test_momentum.cc).
ReducedBodyData centred_free_strip(double length, double height, int cells)
{
  mbs::test::TrussBeamSpec spec;
  spec.clamped = false;
  spec.n_modes = 4;
  spec.length = length;
  spec.height = height;
  spec.n_cells = cells;
  auto body = mbs::test::make_truss_beam(spec).body;
  REQUIRE(body.translation_coupling.norm() < 1e-9 * body.mass);
  const Vector2 c = body.center_of_mass;
  for (int i = 0; i < body.n_nodes(); ++i)
    body.nodes.row(i) -= c.transpose();
  body.c_xx -= body.mass * c * c.transpose();
  body.center_of_mass.setZero();
  return body;
}
} // namespace

TEST_CASE("contact: a 2D box dropped on the floor bounces to e^2 h0", "[coupling][contact]")
{
  const double h0 = 0.2;
  for (double e : {0.5, 0.8})
  {
    const double apex = bounce_height_2d(e, h0);
    INFO("e = " << e << ": bounce " << apex << " m, expected " << e * e * h0);
    CHECK(apex == Approx(e * e * h0).epsilon(0.05));
  }
}

TEST_CASE("contact: a 3D box of triangles dropped on the floor bounces to e^2 h0",
          "[coupling][contact]")
{
  const double h0 = 0.2, e = 0.6;
  const double apex = bounce_height_3d(e, h0);
  INFO("bounce " << apex << " m, expected " << e * e * h0);
  CHECK(apex == Approx(e * e * h0).epsilon(0.05));
}

TEST_CASE("contact: a 3D box sticks on an incline below tan(phi) = mu and slides above",
          "[coupling][contact][heavy]")
{
  const double mu = 0.4;
  double distance = 0;
  const double phi_stick = std::atan(0.8 * mu);
  slide_on_incline_3d(phi_stick, mu, distance);
  const double free_slide = 0.5 * g * std::sin(phi_stick) * 0.3 * 0.3;
  INFO("sticking: moved " << distance << " m in 0.3 s (frictionless: " << free_slide << " m)");
  CHECK(std::abs(distance) < 1e-5 * free_slide);
  const double phi = std::atan(1.5 * mu);
  const double a = slide_on_incline_3d(phi, mu, distance);
  const double expected = g * (std::sin(phi) - mu * std::cos(phi));
  INFO("sliding: a = " << a << " m/s^2, expected " << expected);
  CHECK(a == Approx(expected).epsilon(0.02));
}

TEST_CASE("contact: a block sticks on an incline below tan(phi) = mu and slides above",
          "[coupling][contact]")
{
  const double mu = 0.3;
  SECTION("sticks")
  {
    const double phi = std::atan(0.8 * mu);
    const Slide s = slide_on_incline(phi, mu);
    const double free_slide = 0.5 * g * std::sin(phi) * 0.3 * 0.3; // without friction
    INFO("moved " << s.distance << " m in 0.3 s (frictionless: " << free_slide << " m)");
    CHECK(std::abs(s.distance) < 1e-5 * free_slide);
  }
  SECTION("slides with g (sin - mu cos)")
  {
    for (double ratio : {1.5, 3.0})
    {
      const double phi = std::atan(ratio * mu);
      const double expected = g * (std::sin(phi) - mu * std::cos(phi));
      const Slide s = slide_on_incline(phi, mu);
      INFO("tan(phi) = " << ratio << " mu: a = " << s.acceleration << " m/s^2, expected "
                         << expected);
      CHECK(s.acceleration == Approx(expected).epsilon(0.02));
    }
  }
}

namespace
{
struct HeadOn
{
  double drift;  ///< largest |p(t) - p0| / |p0|
  double e0, e1; ///< kinetic + strain energy before and after, J/m
  double v_right;
};

/// Two free flexible bars meeting head-on with restitution e (see the header).
HeadOn head_on(double e)
{
  const double length = 0.06, height = 0.006, v0 = 1.0;
  std::vector<std::unique_ptr<coupling::MultibodyCoupledBody<2>>> bars;
  std::vector<mbs::FloatingFrameBody<2>*> bodies;
  double omega_max = 0;
  for (int k = 0; k < 2; ++k)
  {
    mbs::IntegratorOptions options;
    options.scheme = mbs::IntegratorOptions::Scheme::symplectic_euler;
    auto system = std::make_unique<mbs::MultibodySystem<2>>(options);
    const auto data = centred_free_strip(length, height, 10);
    omega_max = std::max(omega_max, 2 * M_PI * data.frequencies_hz.maxCoeff());
    auto body = std::make_unique<mbs::FloatingFrameBody<2>>(data);
    // Bar 0 on the left moving right, bar 1 at rest, a gap of 2 mm, offset by a
    // quarter of the height so that corners meet faces.
    body->set_pose(k == 0 ? Vector2(0, 0) : Vector2(length + 0.002, height / 4), 0.0);
    body->set_frame_velocity(Vector2(k == 0 ? v0 : 0, 0), Eigen::Matrix<double, 1, 1>::Zero());
    bodies.push_back(body.get());
    auto* skin = body.get();
    system->add_body(std::move(body));
    bars.push_back(
        std::make_unique<coupling::MultibodyCoupledBody<2>>("flexible", std::move(system), *skin));
  }
  coupling::ContactParameters p;
  p.restitution = e;
  p.friction = 0.3;
  coupling::ContactSimulation<2> sim(p);
  sim.add_body(*bars[0], "left");
  sim.add_body(*bars[1], "right");
  auto energy = [&]()
  {
    double e = 0;
    for (auto* b : bodies)
      e += b->kinetic_energy() + b->strain_energy();
    return e;
  };
  // Explicit body step: well inside its stability limit 2 / omega_max.
  const double dt = std::min(0.1 / omega_max, 1e-5);
  const Vector2 p0 = sim.total_momentum();
  const double e0 = energy();
  double worst = 0;
  bool touched = false;
  int after = 0;
  for (int step = 0; step < 200000 && after < 200; ++step)
  {
    sim.step(dt);
    worst = std::max(worst, (sim.total_momentum() - p0).norm());
    if (sim.contact().n_contacts() > 0)
      touched = true;
    else if (touched)
      ++after;
  }
  const double e1 = energy();
  const double v_right = bars[1]->linear_momentum().x() / bars[1]->mass();
  UNSCOPED_INFO("e = " << e << ": dt " << dt << " s, momentum drift " << worst / p0.norm()
                       << " relative, energy " << e0 << " -> " << e1 << " J/m, right bar "
                       << v_right << " m/s");
  REQUIRE(touched);
  REQUIRE(after >= 200); // the bars have separated
  return {worst / p0.norm(), e0, e1, v_right};
}
} // namespace

TEST_CASE("contact: two free flexible bars collide head-on, momentum conserved, energy lost",
          "[coupling][contact]")
{
  const HeadOn damped = head_on(0.7);
  CHECK(damped.drift <= 1e-9);
  CHECK(damped.e1 <= damped.e0);
  CHECK(damped.e1 < 0.95 * damped.e0); // the damped contact did take energy out
  CHECK(damped.v_right > 0.3);         // the momentum really was exchanged (v0 = 1 m/s)
  // Without damping only friction (and the modes' share) takes energy: a contact
  // force that pumped energy, as a force sampled at the wrong time does, would show.
  const HeadOn elastic = head_on(1.0);
  CHECK(elastic.drift <= 1e-9);
  CHECK(elastic.e1 <= elastic.e0);
  CHECK(elastic.e1 > 0.99 * elastic.e0);
}

TEST_CASE("contact: a wall's corner poking into a body between its nodes pushes it out",
          "[coupling][contact]")
{
  // A tent-shaped wall whose apex (0, 0.05) lies 1 mm inside the bottom face of a box,
  // midway between two of its skin nodes (12.5 mm apart), no node near a wall face.
  sph::WallSurface<2> tent;
  tent.name = "tent";
  tent.vertices = {Vector2(0.1, 0), Vector2(0, 0.05), Vector2(-0.1, 0)};
  tent.faces = {{0, 1}, {1, 2}};
  const double h = 0.05;
  auto box = free_box_2d(Vector2(0.00625, 0.05 - 0.001 + h / 2), 0, 0.1, h);
  coupling::ContactParameters p;
  p.stiffness = 1e5;
  coupling::ContactSimulation<2> sim(p);
  sim.add_wall(tent);
  sim.add_body(*box, "box");
  sim.step(1e-5);
  const auto& c = sim.contact();
  REQUIRE(c.n_contacts() == 1);
  Vector2 on_body = Vector2::Zero(), on_wall = Vector2::Zero();
  for (const auto& f : c.body_forces(0))
    on_body += f;
  for (const auto& f : c.obstacle_forces(0))
    on_wall += f;
  // Evaluated half a step ahead at rest: the overlap is the 1 mm (to the fall in dt).
  CHECK(on_body.x() == Approx(0).margin(1e-9));
  CHECK(on_body.y() == Approx(1e5 * 1e-3).epsilon(1e-3));
  CHECK((on_body + on_wall).norm() < 1e-12 * on_body.norm());
}

namespace
{
/// A skin at rest at given positions (for geometry checks of the contact search).
class StaticSkin : public mbs::SkinBody<2>
{
public:
  StaticSkin(std::vector<Vector2> x, std::vector<std::array<int, 2>> faces)
      : x_(std::move(x)), faces_(std::move(faces))
  {
  }
  std::size_t n_skin_nodes() const override { return x_.size(); }
  const std::vector<std::array<int, 2>>& skin_faces() const override { return faces_; }
  void skin_positions(std::vector<Vector2>& x) const override { x = x_; }
  void skin_velocities(std::vector<Vector2>& v) const override
  {
    v.assign(x_.size(), Vector2::Zero());
  }
  void set_skin_forces(const std::vector<Vector2>&) override {}

private:
  std::vector<Vector2> x_;
  std::vector<std::array<int, 2>> faces_;
};

/// Regular n-gon of radius r (counter-clockwise: outward normals) about c.
StaticSkin polygon(const Vector2& c, double r, int n, double phase)
{
  std::vector<Vector2> x;
  std::vector<std::array<int, 2>> f;
  for (int k = 0; k < n; ++k)
  {
    const double a = phase + 2 * M_PI * k / n;
    x.push_back(c + r * Vector2(std::cos(a), std::sin(a)));
    f.push_back({k, (k + 1) % n});
  }
  return StaticSkin(x, f);
}
} // namespace

TEST_CASE("contact: the cell grid finds the same contacts wherever the cells fall",
          "[coupling][contact]")
{
  // 40 overlapping 12-gons (radius 1 cm, edges 5.2 mm) and a floor. The cell grid's
  // cells (the longest mean edge, 5.2 mm) fall differently on the same configuration
  // shifted by a fraction of a cell: a search that missed a face across a cell border
  // would find other contacts. Reference: translation invariance of the geometry.
  auto run = [](const Vector2& shift, int& contacts, double& force)
  {
    std::vector<StaticSkin> skins;
    unsigned seed = 12345;
    auto uniform = [&seed]()
    {
      seed = seed * 1103515245u + 12345u;
      return double((seed >> 8) & 0xFFFF) / 65536.0;
    };
    for (int k = 0; k < 40; ++k)
      skins.push_back(polygon(shift + Vector2(0.2 * uniform(), 0.0085 + 0.05 * uniform()), 0.01, 12,
                              2 * M_PI * uniform()));
    coupling::ContactParameters p;
    p.stiffness = 1e4;
    p.friction = 0;
    p.thickness = 0.004;
    coupling::ContactModel<2> model(p);
    const auto floor = segment_wall(shift + Vector2(1, 0), shift + Vector2(-1, 0));
    model.add_obstacle(floor);
    for (std::size_t k = 0; k < skins.size(); ++k)
      model.add_body(skins[k], 0.1, "p" + std::to_string(k));
    model.compute(1e-5);
    contacts = model.n_contacts();
    force = 0;
    for (int b = 0; b < model.n_bodies(); ++b)
      for (const auto& f : model.body_forces(b))
        force += f.norm();
  };
  int n0 = 0;
  double f0 = 0;
  run(Vector2::Zero(), n0, f0);
  INFO("contacts " << n0 << ", sum |f| " << f0 << " N/m");
  REQUIRE(n0 > 40); // the polygons do overlap each other and the floor
  for (const Vector2& shift :
       {Vector2(0.00131, 0.00277), Vector2(-0.0041, 0.0019), Vector2(0.5003, -0.2501)})
  {
    int n = 0;
    double f = 0;
    run(shift, n, f);
    CHECK(n == n0);
    CHECK(f == Approx(f0).epsilon(1e-9));
  }
}
