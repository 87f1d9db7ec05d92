// Chip meshes (`chipflex mesh chip`, meshes/chip_mesher.h) through the reduction with the
// curved (isoparametric) geometry of their second-order nodes:
//   - the volume of each shape against its exact value (w t times the centre-curve length;
//     for the spiral w t times the integral of r dphi),
//   - a free ring's in-plane bending frequencies against classical inextensional ring
//     theory, omega_n = sqrt(E I / (rho A R^4)) n (n^2 - 1) / sqrt(n^2 + 1) (R. D. Blevins,
//     Formulas for Natural Frequency and Mode Shape, 1979, Table 9-1; Love's thin ring),
//   - a free helical chip's six rigid modes and its mass, centre of mass and inertia tensor
//     against a high-order quadrature of the exact Frenet-swept chip.
#include "fem/eigen_solver.h"
#include "fem/elastic_body.h"
#include "fem_test_support.h"
#include "meshes/chip_mesher.h"
#include "meshes/gmsh_session.h"

#include <catch2/catch.hpp>
#include <gmsh.h>
#include <iostream>

using namespace chipflex;
using namespace chipflex::fem;
using namespace chipflex::fem::testing;
using Shape = meshes::ChipMeshSpec::Shape;

namespace
{
std::string chip_mesh(const meshes::ChipMeshSpec& spec, const std::string& name)
{
  const std::string path = scratch(name + ".msh");
  meshes::write_chip_mesh(spec, path);
  return path;
}

meshes::ChipMeshSpec chip(Shape shape)
{
  meshes::ChipMeshSpec spec;
  spec.shape = shape;
  spec.width = 2e-3;
  spec.thickness = 0.2e-3;
  spec.curl_radius = 3e-3;
  spec.pitch = shape == Shape::spiral ? 3e-3 : 2e-3;
  spec.turns = 2;
  spec.arc_angle = 180;
  spec.length = 10e-3;
  spec.size = 1e-3;
  return spec;
}

/// Steel (the chip material of the drilling cases): E, nu, rho.
Material steel()
{
  return {2.1e11, 0.3, 7850, false};
}

/// The reduction of a free steel body meshed in `mesh_file` to `n_modes` elastic modes.
ReductionSettings steel_body(const std::string& mesh_file, unsigned int n_modes)
{
  ReductionSettings s;
  s.mesh_file = mesh_file;
  s.material = steel();
  s.n_modes = n_modes;
  return s;
}
} // namespace

TEST_CASE("chip meshes: volume of every shape within 0.5 % of the exact value", "[fem][chip]")
{
  for (const auto& [shape, name, angle] :
       std::vector<std::tuple<Shape, std::string, double>>{{Shape::ribbon, "ribbon", 180},
                                                           {Shape::arc, "arc", 180},
                                                           {Shape::arc, "ring", 360},
                                                           {Shape::spiral, "spiral", 180},
                                                           {Shape::helical, "helical", 180}})
  {
    auto spec = chip(shape);
    spec.arc_angle = angle;
    const std::string path = chip_mesh(spec, "volume_" + name);
    const GmshMeshData mesh = read_gmsh_mesh(path);
    CHECK(mesh.order == 2);
    CHECK_FALSE(mesh.simplex);
    CHECK(mesh.cell_groups.count("body"));
    CHECK(mesh.face_groups.count("skin"));
    // A ring is closed: no ends.
    CHECK(mesh.face_groups.count("start") == (name == "ring" ? 0u : 1u));
    CHECK(mesh.face_groups.count("end") == (name == "ring" ? 0u : 1u));

    ReductionSettings s = steel_body(path, 1);
    const auto body = reduce_body(s);
    // The ends are the sections at the centre curve's start and end: all their nodes lie
    // within half the section's diagonal of the centre point there.
    if (name != "ring")
    {
      const double angle =
                       shape == Shape::arc ? spec.arc_angle * M_PI / 180 : 2 * M_PI * spec.turns,
                   r = shape == Shape::spiral ? spec.curl_radius + spec.pitch * spec.turns
                                              : spec.curl_radius;
      const Eigen::Vector3d first = shape == Shape::ribbon
                                        ? Eigen::Vector3d::Zero()
                                        : Eigen::Vector3d(spec.curl_radius, 0, 0),
                            last = shape == Shape::ribbon
                                       ? Eigen::Vector3d(spec.length, 0, 0)
                                       : Eigen::Vector3d(r * std::cos(angle), r * std::sin(angle),
                                                         shape == Shape::helical
                                                             ? spec.pitch * spec.turns
                                                             : 0.);
      for (const auto& [group, point] : {std::pair{"start", first}, std::pair{"end", last}})
      {
        const auto& nodes = body.node_sets.at(group);
        CHECK(nodes.size() == 5u * 5u); // 2 x 2 quadratic cells: 5 x 5 nodes
        double farthest = 0;
        for (const int i : nodes)
          farthest = std::max(farthest, (body.nodes.row(i).transpose() - point).norm());
        INFO(name << " " << group);
        CHECK(farthest < 1.0001 * 0.5 * std::hypot(spec.width, spec.thickness));
      }
    }
    const double exact = meshes::chip_volume(spec), volume = body.mass / s.material.density;
    s.straight_sided = true;
    const double faceted = reduce_body(s).mass / s.material.density;
    std::cout << name << ": volume " << volume << " m^3, exact " << exact << ", curved "
              << 100 * (volume / exact - 1) << " %, straight-sided " << 100 * (faceted / exact - 1)
              << " %\n";
    INFO(name << ": volume " << volume << ", exact " << exact);
    CHECK(volume == Approx(exact).epsilon(0.005));
    // The curved geometry is exact to the quadratic interpolation of the chip (~1e-6 here):
    // far inside the 0.5 %, and a faceted mesh would miss it (below for the ring).
    CHECK(volume == Approx(exact).epsilon(1e-4));
    if (shape != Shape::ribbon)
      CHECK(std::abs(faceted / exact - 1) > 10 * std::abs(volume / exact - 1));
  }
}

namespace
{
struct RingMode
{
  double frequency_hz;
  int n;               ///< dominant circumferential wave number of the radial motion
  double out_of_plane; ///< share of the mode's motion along z
};

/// The body's modes with the wave number of their radial displacement on the ring.
std::vector<RingMode> ring_modes(const ReducedBodyData& body)
{
  std::vector<RingMode> modes;
  for (int k = 0; k < body.n_modes(); ++k)
  {
    double in_plane = 0, axial = 0;
    std::vector<double> power(8, 0.);
    for (int i = 0; i < body.n_nodes(); ++i)
    {
      in_plane += std::pow(body.psi(3 * i, k), 2) + std::pow(body.psi(3 * i + 1, k), 2);
      axial += std::pow(body.psi(3 * i + 2, k), 2);
    }
    // Project the radial (in-plane modes) or axial motion on cos/sin(n theta).
    for (int n = 0; n < 8; ++n)
    {
      double c = 0, s = 0;
      for (int i = 0; i < body.n_nodes(); ++i)
      {
        const double theta = std::atan2(body.nodes(i, 1), body.nodes(i, 0));
        const double value = axial > in_plane ? body.psi(3 * i + 2, k)
                                              : body.psi(3 * i, k) * std::cos(theta) +
                                                    body.psi(3 * i + 1, k) * std::sin(theta);
        c += value * std::cos(n * theta);
        s += value * std::sin(n * theta);
      }
      power[n] = c * c + s * s;
    }
    const int n = std::max_element(power.begin(), power.end()) - power.begin();
    modes.push_back({body.frequencies_hz[k], n, axial / (axial + in_plane)});
  }
  return modes;
}
} // namespace

TEST_CASE("free ring: in-plane bending n = 2, 3 within 1 % of ring theory", "[fem][chip]")
{
  // A thin steel ring: R = 10 mm, radial width (the in-plane bending depth) 0.5 mm,
  // w / R = 0.05, axial thickness 1 mm; 51 quadratic hexahedra around. Thin-ring theory
  // neglects shear and rotary inertia: the converged FE values (816 hexahedra) lie 0.10 %
  // (n = 2) and 0.29 % (n = 3) below it; this mesh adds about +0.4 % (membrane locking of
  // curved quadratic elements, docs/chips.md).
  meshes::ChipMeshSpec spec;
  spec.shape = Shape::arc;
  spec.arc_angle = 360;
  spec.curl_radius = 0.01;
  spec.width = 0.5e-3;
  spec.thickness = 1e-3;
  spec.size = 1.25e-3;
  ReductionSettings s = steel_body(chip_mesh(spec, "ring"), 8);
  const double R = spec.curl_radius, A = spec.width * spec.thickness,
               I = spec.thickness * std::pow(spec.width, 3) / 12;
  auto theory = [&](int n)
  {
    return std::sqrt(s.material.youngs_modulus * I / (s.material.density * A * std::pow(R, 4))) *
           n * (n * n - 1) / std::sqrt(n * n + 1.) / (2 * M_PI);
  };
  for (const bool straight : {false, true})
  {
    s.straight_sided = straight;
    const auto body = reduce_body(s);
    const auto modes = ring_modes(body);
    for (const int n : {2, 3})
    {
      std::vector<double> found;
      for (const auto& m : modes)
        if (m.n == n && m.out_of_plane < 1e-3)
          found.push_back(m.frequency_hz);
      // Each ring mode comes as a degenerate pair (cos and sin n theta).
      REQUIRE(found.size() == 2);
      CHECK(found[1] == Approx(found[0]).epsilon(1e-6));
      const double error = found[0] / theory(n) - 1;
      std::cout << "ring n = " << n << (straight ? ", straight-sided" : ", curved")
                << " mapping: " << found[0] << " Hz, ring theory " << theory(n) << " Hz, "
                << 100 * error << " %\n";
      if (!straight)
        CHECK(std::abs(error) < 0.01);
    }
    const double mass = s.material.density * meshes::chip_volume(spec);
    std::cout << "ring mass, " << (straight ? "straight-sided" : "curved")
              << " mapping: " << 100 * (body.mass / mass - 1) << " % off rho V\n";
    if (!straight)
      CHECK(body.mass == Approx(mass).epsilon(1e-5));
  }
}

namespace
{
/// Mass properties of the exact helical chip, c(phi) + u N + v B with the volume element
/// (1 - kappa u) s dphi du dv (s = |c'|, kappa = R / s^2; the torsion terms drop out of the
/// Jacobian), by Gauss-Legendre quadrature: 5 points in u and v (the integrand is
/// polynomial of degree 3 there, exact) and 8 points on each of 64 intervals per turn.
struct MassProperties
{
  double mass;
  Eigen::Vector3d centre;
  Eigen::Matrix3d inertia; ///< about the centre
};

MassProperties exact_helix(const meshes::ChipMeshSpec& spec, double rho)
{
  static const double gx[] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                              -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                              0.7966664774136267,  0.9602898564975363};
  static const double gw[] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                              0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                              0.2223810344533745, 0.1012285362903763};
  static const double x5[] = {-0.9061798459386640, -0.5384693101056831, 0, 0.5384693101056831,
                              0.9061798459386640};
  static const double w5[] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                              0.4786286704993665, 0.2369268850561891};
  const double R = spec.curl_radius, h = spec.pitch / (2 * M_PI), s = std::hypot(R, h),
               kappa = R / (s * s), total = 2 * M_PI * spec.turns;
  const int intervals = static_cast<int>(std::ceil(64 * spec.turns));
  double m = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (int k = 0; k < intervals; ++k)
    for (int a = 0; a < 8; ++a)
    {
      const double phi = total * (k + 0.5 * (1 + gx[a])) / intervals,
                   d_phi = total / intervals * 0.5 * gw[a];
      const Eigen::Vector3d c(R * std::cos(phi), R * std::sin(phi), h * phi),
          n(-std::cos(phi), -std::sin(phi), 0),
          b(h * std::sin(phi) / s, -h * std::cos(phi) / s, R / s);
      for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
        {
          const double u = 0.5 * spec.width * x5[i], v = 0.5 * spec.thickness * x5[j];
          const double dv = rho * (1 - kappa * u) * s * d_phi * 0.5 * spec.width * w5[i] * 0.5 *
                            spec.thickness * w5[j];
          const Eigen::Vector3d x = c + u * n + v * b;
          m += dv;
          first += dv * x;
          second += dv * x * x.transpose();
        }
    }
  MassProperties p;
  p.mass = m;
  p.centre = first / m;
  const Eigen::Matrix3d about_centre = second - m * p.centre * p.centre.transpose();
  p.inertia = about_centre.trace() * Eigen::Matrix3d::Identity() - about_centre;
  return p;
}
} // namespace

TEST_CASE("free helical chip: six rigid modes, exact mass properties", "[fem][chip]")
{
  // Two turns, R = 3 mm, pitch 2 mm, 2 x 0.2 mm section, 1 mm elements (160 hexahedra).
  const auto spec = chip(Shape::helical);
  const std::string path = chip_mesh(spec, "helix");
  ReductionSettings s = steel_body(path, 2);
  // The reduction itself requires six rigid modes (|lambda| < 1e-4 of the first elastic).
  const auto reduced = reduce_body(s);
  const double first_elastic = std::pow(2 * M_PI * reduced.frequencies_hz[0], 2);

  // The spectrum's bottom, computed afresh: exactly six eigenvalues at zero.
  const GmshMeshData mesh = read_gmsh_mesh(path);
  ElasticBody<3> body(mesh, steel(), 2, "", MPI_COMM_WORLD);
  body.setup_system();
  body.assemble_system();
  const auto solution =
      solve_eigenproblem(body.stiffness_matrix, body.mass_matrix, 8, -1e-2 * first_elastic,
                         body.new_vector(), body.node_block_size);
  std::cout << "helical chip: first elastic mode " << reduced.frequencies_hz[0]
            << " Hz; eigenvalues / first elastic:";
  for (int k = 0; k < 8; ++k)
    std::cout << " " << solution.eigenvalues[k] / first_elastic;
  std::cout << "\n";
  for (int k = 0; k < 6; ++k)
    // Isoparametric elements hold rigid motion exactly: zero up to the solver's round-off.
    CHECK(std::abs(solution.eigenvalues[k]) < 1e-6 * first_elastic);
  CHECK(solution.eigenvalues[6] == Approx(first_elastic).epsilon(1e-6));

  const auto exact = exact_helix(spec, s.material.density);
  // The quadrature reproduces the analytic mass rho w t L and
  // I_zz = rho L t [w R^2 + (1 + 2 kappa R) w^3 / 12 + w (h / s)^2 t^2 / 12] (about the axis;
  // with whole turns the centre of mass lies on it, at half the height).
  const double R = spec.curl_radius, h = spec.pitch / (2 * M_PI), sh = std::hypot(R, h),
               kappa = R / (sh * sh), w = spec.width, t = spec.thickness,
               L = meshes::chip_centre_length(spec), rho = s.material.density;
  REQUIRE(exact.mass == Approx(rho * meshes::chip_volume(spec)).epsilon(1e-12));
  const double izz =
      rho * L * t *
      (w * R * R + (1 + 2 * kappa * R) * w * w * w / 12 + w * std::pow(h / sh, 2) * t * t / 12);
  REQUIRE(exact.inertia(2, 2) == Approx(izz).epsilon(1e-10));
  REQUIRE(exact.centre.head<2>().norm() < 1e-12 * R);
  REQUIRE(exact.centre[2] == Approx(spec.pitch * spec.turns / 2).epsilon(1e-12));

  // The same integrals over the meshed (quadratic) geometry itself, by gmsh's own
  // Jacobians and a high-order Gauss rule: what the body's consistent mass matrix must
  // reproduce to round-off, whatever the geometry's distance from the exact chip.
  MassProperties meshed{0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero()};
  {
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
    meshes::with_gmsh_model(path,
                            [&]
                            {
                              gmsh::open(path);
                              std::vector<int> types;
                              gmsh::model::mesh::getElementTypes(types, 3);
                              for (const int type : types)
                              {
                                std::vector<double> local, weights, jacobians, det, x;
                                gmsh::model::mesh::getIntegrationPoints(type, "Gauss12", local,
                                                                        weights);
                                gmsh::model::mesh::getJacobians(type, local, jacobians, det, x);
                                for (std::size_t q = 0; q < det.size(); ++q)
                                {
                                  const double dm = rho * det[q] * weights[q % weights.size()];
                                  const Eigen::Vector3d p(x[3 * q], x[3 * q + 1], x[3 * q + 2]);
                                  meshed.mass += dm;
                                  first += dm * p;
                                  second += dm * p * p.transpose();
                                }
                              }
                            });
    meshed.centre = first / meshed.mass;
    const Eigen::Matrix3d about = second - meshed.mass * meshed.centre * meshed.centre.transpose();
    meshed.inertia = about.trace() * Eigen::Matrix3d::Identity() - about;
  }

  for (const bool straight : {false, true})
  {
    s.straight_sided = straight;
    const auto b = straight ? reduce_body(s) : reduced;
    auto errors = [&](const MassProperties& reference)
    {
      return std::array<double, 3>{
          b.mass / reference.mass - 1, (b.center_of_mass - reference.centre).norm() / R,
          (b.inertia_tensor - reference.inertia).norm() / reference.inertia.norm()};
    };
    const auto to_exact = errors(exact), to_mesh = errors(meshed);
    std::cout << "helical chip, " << (straight ? "straight-sided" : "curved")
              << " mapping, relative errors against the exact chip: mass " << to_exact[0]
              << ", centre " << to_exact[1] << " R, inertia " << to_exact[2]
              << "; against the meshed geometry: " << to_mesh[0] << ", " << to_mesh[1] << ", "
              << to_mesh[2] << "\n";
    if (!straight)
    {
      // The body integrates its own geometry: the mass exactly (det J is of degree 5 per
      // direction, within the 3-point Gauss rule of the assembly), the second moments to
      // that rule's accuracy (x x^T det J is of degree 9: ~4e-8 here).
      CHECK(std::abs(to_mesh[0]) < 1e-12);
      CHECK(to_mesh[1] < 1e-9);
      CHECK(to_mesh[2] < 1e-6);
      // That geometry is the chip up to the quadratic interpolation (1 mm elements, 18
      // degrees of the helix each: ~2e-5).
      CHECK(std::abs(to_exact[0]) < 1e-4);
      CHECK(to_exact[1] < 1e-4);
      CHECK(to_exact[2] < 1e-4);
    }
    else // the faceted chip misses by far more: the curved tolerances above mean something
      CHECK(std::abs(to_exact[0]) > 1e-3);
  }
}

namespace
{
/// A second-order gmsh mesh of an OpenCASCADE cylinder (3D: r 2 mm, height 10 mm) or
/// annulus (2D: radii 5 and 10 mm), triangles/tetrahedra or recombined quadrilaterals.
std::string curved_mesh(int dim, bool quads, bool complete = true)
{
  const std::string path = scratch("curved_" + std::to_string(dim) + (quads ? "q" : "s") +
                                   (complete ? "" : "_incomplete") + ".msh");
  meshes::with_gmsh_model(
      path,
      [&]
      {
        gmsh::model::add("curved");
        namespace occ = gmsh::model::occ;
        if (dim == 3)
          occ::addCylinder(0, 0, 0, 0, 0, 0.01, 0.002);
        else
        {
          gmsh::vectorpair out;
          std::vector<gmsh::vectorpair> map;
          occ::cut({{2, occ::addDisk(0, 0, 0, 0.01, 0.01)}},
                   {{2, occ::addDisk(0, 0, 0, 0.005, 0.005)}}, out, map);
        }
        occ::synchronize();
        gmsh::vectorpair bodies, faces;
        gmsh::model::getEntities(bodies, dim);
        gmsh::model::getEntities(faces, dim - 1);
        std::vector<int> b, f;
        for (const auto& e : bodies)
          b.push_back(e.second);
        for (const auto& e : faces)
          f.push_back(e.second);
        gmsh::model::setPhysicalName(dim, gmsh::model::addPhysicalGroup(dim, b), "body");
        gmsh::model::setPhysicalName(dim - 1, gmsh::model::addPhysicalGroup(dim - 1, f), "skin");
        gmsh::option::setNumber("Mesh.MeshSizeMax", dim == 3 ? 0.0015 : 0.003);
        gmsh::option::setNumber("Mesh.RecombineAll", quads ? 1 : 0);
        gmsh::model::mesh::generate(dim);
        gmsh::option::setNumber("Mesh.SecondOrderIncomplete", complete ? 0 : 1);
        gmsh::model::mesh::setOrder(2);
        gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
        gmsh::write(path);
      });
  return path;
}
} // namespace

/// The volume (3D) or area (2D) of a mesh's cells by gmsh's own Jacobians, high-order Gauss.
double gmsh_measure(const std::string& path, int dim)
{
  double measure = 0;
  meshes::with_gmsh_model(path,
                          [&]
                          {
                            gmsh::open(path);
                            std::vector<int> types;
                            gmsh::model::mesh::getElementTypes(types, dim);
                            for (const int type : types)
                            {
                              std::vector<double> local, weights, jacobians, det, x;
                              gmsh::model::mesh::getIntegrationPoints(type, "Gauss8", local,
                                                                      weights);
                              gmsh::model::mesh::getJacobians(type, local, jacobians, det, x);
                              for (std::size_t q = 0; q < det.size(); ++q)
                                measure += det[q] * weights[q % weights.size()];
                            }
                          });
  return measure;
}

TEST_CASE("second-order gmsh meshes of every cell kind stay curved", "[fem][chip]")
{
  // Exact: the cylinder's volume pi r^2 h, the annulus's area pi (R^2 - r^2) (per metre).
  for (const auto& [dim, quads, exact] :
       std::vector<std::tuple<int, bool, double>>{{3, false, M_PI * 0.002 * 0.002 * 0.01},
                                                  {2, false, M_PI * (1e-4 - 2.5e-5)},
                                                  {2, true, M_PI * (1e-4 - 2.5e-5)}})
  {
    // A free body: the reduction checks its rigid modes are at zero.
    ReductionSettings s = steel_body(curved_mesh(dim, quads), 2);
    s.material.density = 1;
    const double curved = reduce_body(s).mass;
    s.straight_sided = true;
    const double faceted = reduce_body(s).mass;
    const double meshed = gmsh_measure(s.mesh_file, dim);
    INFO(dim << "D " << (quads ? "quadrilaterals" : "simplices") << ": curved " << curved
             << ", straight-sided " << faceted << ", gmsh " << meshed << ", exact " << exact);
    // The body has gmsh's curved geometry to round-off, which is the exact shape to the
    // quadratic interpolation of its boundary; the straight-sided cells are not.
    CHECK(curved == Approx(meshed).epsilon(1e-12));
    CHECK(curved == Approx(exact).epsilon(2e-4));
    CHECK(std::abs(faceted / meshed - 1) > 1e-4);
  }
  // Incomplete second-order cells have no node in the middle of their faces: rejected with
  // the curved geometry, read straight-sided on request.
  // A valid material, so that the throw below is the mesh's.
  ReductionSettings s = steel_body(curved_mesh(2, true, false), 2);
  CHECK_THROWS_AS(reduce_body(s), InputError);
  s.straight_sided = true;
  CHECK_NOTHROW(reduce_body(s));
}

TEST_CASE("free ribbon chip: one or two elastic modes reduce as the first of more", "[fem][chip]")
{
  // The flute's ribbon, 10 x 2 x 0.1 mm, 0.5 mm elements: so slender that, asked for one
  // elastic mode only, the reduction once took its rigid eigenvalues for unresolved ones
  // and refused the body ("does not have exactly 6 rigid-body modes").
  auto spec = chip(Shape::ribbon);
  spec.thickness = 0.1e-3;
  spec.size = 0.5e-3;
  const std::string path = chip_mesh(spec, "ribbon");
  ReductionSettings s = steel_body(path, 4);
  const auto four = reduce_body(s);
  for (const unsigned int n : {1u, 2u})
  {
    s.n_modes = n;
    const auto few = reduce_body(s);
    REQUIRE(few.frequencies_hz.size() == n);
    for (unsigned int k = 0; k < n; ++k)
      CHECK(few.frequencies_hz[k] == Approx(four.frequencies_hz[k]).epsilon(1e-8));
  }
}
