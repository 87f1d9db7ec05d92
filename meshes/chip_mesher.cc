#include "meshes/chip_mesher.h"

#include "common/input_error.h"
#include "meshes/gmsh_session.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <gmsh.h>
#include <limits>
#include <sstream>
#include <unistd.h>

namespace chipflex::meshes
{
namespace
{
using Vec = std::array<double, 3>;

Vec operator+(Vec a, const Vec& b)
{
  for (int d = 0; d < 3; ++d)
    a[d] += b[d];
  return a;
}
Vec operator*(double s, Vec a)
{
  for (auto& x : a)
    x *= s;
  return a;
}
double dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double norm(const Vec& a)
{
  return std::sqrt(dot(a, a));
}

std::string text(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

constexpr double two_pi = 2 * M_PI;

/// Total angle of the centre curve about the z axis, radians (curved shapes).
double total_angle(const ChipMeshSpec& spec)
{
  return spec.shape == ChipMeshSpec::Shape::arc ? spec.arc_angle * M_PI / 180 : two_pi * spec.turns;
}

/// The helix's axial advance per radian, m (an arc is a helix without rise).
double helix_rise(const ChipMeshSpec& spec)
{
  return spec.shape == ChipMeshSpec::Shape::helical ? spec.pitch / two_pi : 0.;
}

/// Centre-curve point at angle phi (ribbon: at arc length phi).
Vec centre(const ChipMeshSpec& spec, double phi)
{
  switch (spec.shape)
  {
  case ChipMeshSpec::Shape::ribbon:
    return {phi, 0, 0};
  case ChipMeshSpec::Shape::arc:
    return {spec.curl_radius * std::cos(phi), spec.curl_radius * std::sin(phi), 0};
  case ChipMeshSpec::Shape::spiral:
  {
    const double r = spec.curl_radius + spec.pitch * phi / two_pi;
    return {r * std::cos(phi), r * std::sin(phi), 0};
  }
  case ChipMeshSpec::Shape::helical:
    break;
  }
  return {spec.curl_radius * std::cos(phi), spec.curl_radius * std::sin(phi),
          helix_rise(spec) * phi};
}

/// The Frenet frame of the helix (or arc) at angle phi: principal normal (towards the
/// axis), binormal.
void helix_frame(const ChipMeshSpec& spec, double phi, Vec& normal, Vec& binormal)
{
  const double R = spec.curl_radius, h = helix_rise(spec), s = std::hypot(R, h);
  normal = {-std::cos(phi), -std::sin(phi), 0};
  binormal = {h * std::sin(phi) / s, -h * std::cos(phi) / s, R / s};
}

int elements_along(double length, double size)
{
  // The slack of 1 % of an element keeps an exact multiple from getting one element more
  // through rounding (the block mesher does the same).
  return std::max(1, static_cast<int>(std::ceil(length / size - 0.01)));
}

/// Length of the spiral's centre curve r = R + b phi between two angles:
/// int sqrt(r^2 + b^2) dphi = (1 / b) int sqrt(u^2 + b^2) du.
double spiral_length(const ChipMeshSpec& spec, double phi0, double phi1)
{
  const double b = spec.pitch / two_pi;
  auto F = [b](double u)
  { return 0.5 * (u * std::hypot(u, b) + b * b * std::log(u + std::hypot(u, b))); };
  return (F(spec.curl_radius + b * phi1) - F(spec.curl_radius + b * phi0)) / b;
}

/// Elements of the structured chip mesh: along the chip (per sector, for arcs split into
/// sectors), across the width; through the thickness is spec.layers.
struct Divisions
{
  int sectors = 1, along = 1, width = 1;
};

Divisions divisions(const ChipMeshSpec& spec)
{
  Divisions d;
  d.width = elements_along(spec.width, spec.size);
  if (spec.shape == ChipMeshSpec::Shape::arc)
  {
    // Annular sectors of at most 120 degrees: OpenCASCADE arcs stay below 180 degrees,
    // and a ring needs at least three four-sided faces for structured meshing.
    const double angle = total_angle(spec);
    d.sectors = std::max(chip_is_closed(spec) ? 3 : 1,
                         static_cast<int>(std::ceil(angle / (2 * M_PI / 3) - 1e-9)));
    d.along = elements_along(spec.curl_radius * angle / d.sectors, spec.size);
  }
  else if (spec.shape == ChipMeshSpec::Shape::spiral)
    // Quarter turns (see extrude_planar_chip), each with its own number along.
    d.sectors = std::max(1, static_cast<int>(std::ceil(4 * spec.turns - 1e-9)));
  else if (spec.shape == ChipMeshSpec::Shape::helical)
  {
    // Quarter turns (see sweep_helical_chip).
    d.sectors = std::max(1, static_cast<int>(std::ceil(4 * spec.turns - 1e-9)));
    d.along = elements_along(chip_centre_length(spec) / d.sectors, spec.size);
  }
  else
    d.along = elements_along(chip_centre_length(spec), spec.size);
  return d;
}

/// Moves every node of a helical or arc chip onto its place on the exact chip. The mesh is
/// a structured block whose nodes sit, up to the OpenCASCADE sweep's approximation (a
/// relative volume error of ~1e-3 for the Frenet pipe), on the lattice
/// c(phi_i) + u_j N(phi_i) + v_k B(phi_i) with phi, u, v uniform over the chip's angle,
/// width and thickness. Each node's (phi, u, v) is found by projecting it on the exact
/// centre curve (Newton on (x - c(phi)) . c'(phi) = 0) and rounded to the lattice; the
/// node then moves to the exact lattice point, second-order nodes included.
void snap_to_exact_chip(const ChipMeshSpec& spec)
{
  const Divisions division = divisions(spec);
  const double R = spec.curl_radius, h = helix_rise(spec), angle = total_angle(spec);
  const int o = spec.order;
  const long n_phi = static_cast<long>(division.along) * division.sectors * o,
             n_u = division.width * o, n_v = spec.layers * o;
  const double d_phi = angle / n_phi, d_u = spec.width / n_u, d_v = spec.thickness / n_v;
  const bool closed = chip_is_closed(spec);
  std::vector<std::size_t> tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(tags, coords, parametric, -1, -1, false, false);
  std::vector<std::array<long, 3>> taken;
  for (std::size_t i = 0; i < tags.size(); ++i)
  {
    const Vec x{coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]};
    double phi = std::atan2(x[1], x[0]);
    if (phi < 0)
      phi += two_pi;
    if (h > 0)
      phi += two_pi * std::round((x[2] / h - phi) / two_pi);
    for (int iteration = 0; iteration < 20; ++iteration)
    {
      const Vec c = centre(spec, phi), dc{-R * std::sin(phi), R * std::cos(phi), h},
                ddc{-R * std::cos(phi), -R * std::sin(phi), 0};
      const Vec r = x + (-1.0) * c;
      const double f = dot(r, dc), df = -dot(dc, dc) + dot(r, ddc), step = f / df;
      phi -= step;
      if (std::abs(step) < 1e-14)
        break;
    }
    Vec n, b;
    helix_frame(spec, phi, n, b);
    const Vec r = x + (-1.0) * centre(spec, phi);
    const double u = dot(r, n) + spec.width / 2, v = dot(r, b) + spec.thickness / 2;
    std::array<long, 3> lattice{std::lround(phi / d_phi), std::lround(u / d_u),
                                std::lround(v / d_v)};
    if (std::abs(phi / d_phi - lattice[0]) > 0.3 || std::abs(u / d_u - lattice[1]) > 0.3 ||
        std::abs(v / d_v - lattice[2]) > 0.3 || lattice[1] < 0 || lattice[1] > n_u ||
        lattice[2] < 0 || lattice[2] > n_v)
      throw std::runtime_error("a chip mesh node is off the structured lattice (internal)");
    if (closed)
      lattice[0] = ((lattice[0] % n_phi) + n_phi) % n_phi;
    taken.push_back(lattice);
    const double phi_exact = lattice[0] * d_phi;
    helix_frame(spec, phi_exact, n, b);
    const Vec exact = centre(spec, phi_exact) + (lattice[1] * d_u - spec.width / 2) * n +
                      (lattice[2] * d_v - spec.thickness / 2) * b;
    std::vector<double> coordinates(exact.begin(), exact.end()), no_parameters;
    gmsh::model::mesh::setNode(tags[i], coordinates, no_parameters);
  }
  std::sort(taken.begin(), taken.end());
  if (std::adjacent_find(taken.begin(), taken.end()) != taken.end())
    throw std::runtime_error("two chip mesh nodes on one lattice point (internal)");
}

/// Tags of the boundary faces of `volumes` (faces shared by two volumes cancel).
std::vector<int> outer_faces(const gmsh::vectorpair& volumes)
{
  gmsh::vectorpair faces;
  gmsh::model::getBoundary(volumes, faces, true, false, false);
  std::vector<int> tags;
  for (const auto& f : faces)
    tags.push_back(std::abs(f.second));
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  return tags;
}

/// The face among `faces` whose centroid is nearest `target`; it must lie within `tolerance`.
int face_nearest(const std::vector<int>& faces, const Vec& target, double tolerance)
{
  int best = -1;
  double best_distance = std::numeric_limits<double>::max();
  for (const int f : faces)
  {
    Vec c;
    gmsh::model::occ::getCenterOfMass(2, f, c[0], c[1], c[2]);
    const double d = norm(c + (-1.0) * target);
    if (d < best_distance)
      best_distance = d, best = f;
  }
  if (best < 0 || best_distance > tolerance)
    throw std::runtime_error("chip end face not found (internal)");
  return best;
}

/// Planar chips (ribbon, arc, spiral): the chip's face in the plane z = -t/2, meshed with
/// structured quadrilaterals, extruded through the thickness in `layers` hexahedral layers.
gmsh::vectorpair extrude_planar_chip(const ChipMeshSpec& spec)
{
  namespace occ = gmsh::model::occ;
  const double w = spec.width, t = spec.thickness, z0 = -t / 2;
  const Divisions division = divisions(spec);
  const int n_width = division.width;
  std::vector<int> faces;
  // (curve, number of elements) to make transfinite after synchronising.
  std::vector<std::pair<int, int>> curves;

  if (spec.shape == ChipMeshSpec::Shape::ribbon)
  {
    const int face = occ::addRectangle(0, -w / 2, z0, spec.length, w);
    occ::synchronize();
    gmsh::vectorpair boundary;
    gmsh::model::getBoundary({{2, face}}, boundary, false, false, false);
    for (const auto& c : boundary)
    {
      double x0, y0, zz0, x1, y1, zz1;
      gmsh::model::getBoundingBox(1, std::abs(c.second), x0, y0, zz0, x1, y1, zz1);
      const bool along_x = x1 - x0 > y1 - y0;
      curves.emplace_back(std::abs(c.second), along_x ? division.along : n_width);
    }
    faces.push_back(face);
  }
  else if (spec.shape == ChipMeshSpec::Shape::arc)
  {
    // Annular sectors sharing their radial edges, so that a ring closes conformally.
    const bool closed = chip_is_closed(spec);
    const double angle = total_angle(spec), R = spec.curl_radius;
    const int sectors = division.sectors, n_along = division.along;
    const int origin = occ::addPoint(0, 0, z0);
    std::vector<int> inner, outer, radial;
    for (int k = 0; k <= sectors; ++k)
    {
      if (closed && k == sectors)
      {
        inner.push_back(inner.front());
        outer.push_back(outer.front());
        radial.push_back(radial.front());
        break;
      }
      const double phi = angle * k / sectors;
      inner.push_back(occ::addPoint((R - w / 2) * std::cos(phi), (R - w / 2) * std::sin(phi), z0));
      outer.push_back(occ::addPoint((R + w / 2) * std::cos(phi), (R + w / 2) * std::sin(phi), z0));
      radial.push_back(occ::addLine(inner.back(), outer.back()));
      curves.emplace_back(radial.back(), n_width);
    }
    for (int k = 0; k < sectors; ++k)
    {
      const int a = occ::addCircleArc(inner[k], origin, inner[k + 1]);
      const int b = occ::addCircleArc(outer[k], origin, outer[k + 1]);
      curves.emplace_back(a, n_along);
      curves.emplace_back(b, n_along);
      const int loop = occ::addCurveLoop({radial[k], b, radial[k + 1], a});
      faces.push_back(occ::addPlaneSurface({loop}));
    }
    occ::remove({{0, origin}});
  }
  else // spiral
  {
    // Inner and outer edges are the Archimedean spirals r = R -+ w/2 + p phi / (2 pi),
    // interpolated by C2 splines through 64 points per turn (relative error ~1e-7), one
    // face per quarter turn between radial edges: a single face would get its nodes at
    // equal fractions of the unequal inner and outer lengths, badly skewed cells.
    const double angle = total_angle(spec);
    const int sectors = division.sectors,
              per_sector = std::max(4, static_cast<int>(std::ceil(64 * spec.turns / sectors)));
    std::vector<int> inner, outer;
    for (int i = 0; i <= sectors * per_sector; ++i)
    {
      const double phi = angle * i / (sectors * per_sector);
      const Vec c = centre(spec, phi);
      const double r = norm(c);
      const Vec radial{c[0] / r, c[1] / r, 0};
      const Vec p = c + (-w / 2) * radial, q = c + (w / 2) * radial;
      inner.push_back(occ::addPoint(p[0], p[1], z0));
      outer.push_back(occ::addPoint(q[0], q[1], z0));
    }
    std::vector<int> radial_edges;
    for (int k = 0; k <= sectors; ++k)
    {
      radial_edges.push_back(occ::addLine(inner[k * per_sector], outer[k * per_sector]));
      curves.emplace_back(radial_edges.back(), n_width);
    }
    for (int k = 0; k < sectors; ++k)
    {
      const std::vector<int> in(inner.begin() + k * per_sector,
                                inner.begin() + (k + 1) * per_sector + 1),
          out(outer.begin() + k * per_sector, outer.begin() + (k + 1) * per_sector + 1);
      const int a = occ::addSpline(in), b = occ::addSpline(out);
      const int n_along = elements_along(
          spiral_length(spec, angle * k / sectors, angle * (k + 1) / sectors), spec.size);
      curves.emplace_back(a, n_along);
      curves.emplace_back(b, n_along);
      faces.push_back(
          occ::addPlaneSurface({occ::addCurveLoop({radial_edges[k], b, radial_edges[k + 1], a})}));
    }
  }

  gmsh::vectorpair base;
  for (const int f : faces)
    base.emplace_back(2, f);
  gmsh::vectorpair extruded;
  occ::extrude(base, 0, 0, t, extruded, {spec.layers}, {}, true);
  occ::synchronize();
  for (const auto& [c, n] : curves)
    gmsh::model::mesh::setTransfiniteCurve(c, n + 1);
  for (const int f : faces)
  {
    gmsh::model::mesh::setTransfiniteSurface(f);
    gmsh::model::mesh::setRecombine(2, f);
  }
  gmsh::vectorpair volumes;
  for (const auto& e : extruded)
    if (e.first == 3)
      volumes.push_back(e);
  return volumes;
}

/// The helical chip: the section in the normal plane at the start, swept with the Frenet
/// trihedron along C2 splines through the helix (64 points per turn), one quarter turn at
/// a time, each pipe starting from the previous one's end face.
/// Every quarter turn is a six-faced volume meshed as a transfinite block of hexahedra;
/// longer blocks would get poor interior nodes from the transfinite interpolation.
gmsh::vectorpair sweep_helical_chip(const ChipMeshSpec& spec)
{
  namespace occ = gmsh::model::occ;
  const double w = spec.width, t = spec.thickness, angle = total_angle(spec);
  const Divisions division = divisions(spec);
  const int sectors = division.sectors;
  Vec n0, b0;
  helix_frame(spec, 0, n0, b0);
  const Vec c0 = centre(spec, 0);
  std::vector<int> corner;
  for (const auto& [u, v] :
       std::vector<std::pair<double, double>>{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}})
  {
    const Vec p = c0 + (u * w) * n0 + (v * t) * b0;
    corner.push_back(occ::addPoint(p[0], p[1], p[2]));
  }
  std::vector<int> sides;
  for (int k = 0; k < 4; ++k)
    sides.push_back(occ::addLine(corner[k], corner[(k + 1) % 4]));
  int section = occ::addPlaneSurface({occ::addCurveLoop(sides)});

  const int points_per_sector =
      std::max(9, static_cast<int>(std::ceil(64 * spec.turns / sectors)) + 1);
  gmsh::vectorpair volumes;
  for (int k = 0; k < sectors; ++k)
  {
    std::vector<int> path;
    for (int i = 0; i < points_per_sector; ++i)
    {
      const double phi = angle * (k + double(i) / (points_per_sector - 1)) / sectors;
      const Vec c = centre(spec, phi);
      path.push_back(occ::addPoint(c[0], c[1], c[2]));
    }
    const int wire = occ::addWire({occ::addSpline(path)});
    gmsh::vectorpair pipe;
    occ::addPipe({{2, section}}, wire, pipe, "Frenet");
    occ::synchronize();
    volumes.insert(volumes.end(), pipe.begin(), pipe.end());
    if (k + 1 < sectors)
    {
      gmsh::vectorpair faces;
      gmsh::model::getBoundary(pipe, faces, false, false, false);
      std::vector<int> tags;
      for (const auto& f : faces)
        tags.push_back(std::abs(f.second));
      section = face_nearest(tags, centre(spec, angle * (k + 1) / sectors), 0.1 * std::min(w, t));
    }
  }

  // Each pipe copies its start face: merging the copies joins the blocks conformally.
  occ::removeAllDuplicates();
  occ::synchronize();
  volumes.clear();
  gmsh::model::getEntities(volumes, 3);

  // Number of elements by the kind of edge: the straight edges of the sections between
  // the blocks, as long as the width or the thickness, and the edges along the chip.
  gmsh::vectorpair faces, edges;
  gmsh::model::getBoundary(volumes, faces, false, false, false);
  gmsh::model::getBoundary(faces, edges, false, false, false);
  for (auto& e : edges)
    e.second = std::abs(e.second);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& e : edges)
  {
    gmsh::vectorpair ends;
    gmsh::model::getBoundary({{1, e.second}}, ends, false, false, false);
    Vec p0, p1;
    {
      std::vector<double> x;
      gmsh::model::getValue(0, std::abs(ends.at(0).second), {}, x);
      p0 = {x[0], x[1], x[2]};
      gmsh::model::getValue(0, std::abs(ends.at(1).second), {}, x);
      p1 = {x[0], x[1], x[2]};
    }
    const Vec chord = p1 + (-1.0) * p0;
    const double chord_length = norm(chord);
    double length;
    occ::getMass(1, e.second, length);
    int n = division.along;
    if (length < chord_length * (1 + 1e-6) && chord_length < 1.05 * std::max(w, t))
    {
      // The section nearest the edge gives the binormal, the thickness direction.
      int nearest = 0;
      for (int k = 1; k <= sectors; ++k)
        if (norm(p0 + (-1.0) * centre(spec, angle * k / sectors)) <
            norm(p0 + (-1.0) * centre(spec, angle * nearest / sectors)))
          nearest = k;
      Vec n_k, b_k;
      helix_frame(spec, angle * nearest / sectors, n_k, b_k);
      n = std::abs(dot(chord, b_k)) > 0.7 * chord_length ? spec.layers : division.width;
    }
    gmsh::model::mesh::setTransfiniteCurve(e.second, n + 1);
  }
  for (const auto& f : faces)
  {
    gmsh::model::mesh::setTransfiniteSurface(std::abs(f.second));
    gmsh::model::mesh::setRecombine(2, std::abs(f.second));
  }
  for (const auto& v : volumes)
    gmsh::model::mesh::setTransfiniteVolume(v.second);
  return volumes;
}
} // namespace

ChipMeshSpec::Shape parse_chip_shape(const std::string& name, const std::string& where)
{
  if (name == "ribbon")
    return ChipMeshSpec::Shape::ribbon;
  if (name == "arc")
    return ChipMeshSpec::Shape::arc;
  if (name == "spiral")
    return ChipMeshSpec::Shape::spiral;
  if (name == "helical")
    return ChipMeshSpec::Shape::helical;
  throw InputError(where,
                   "unknown chip shape '" + name + "' (expected helical, spiral, arc or ribbon)");
}

bool chip_is_closed(const ChipMeshSpec& spec)
{
  return spec.shape == ChipMeshSpec::Shape::arc && std::abs(spec.arc_angle - 360) < 1e-9;
}

double chip_centre_length(const ChipMeshSpec& spec)
{
  const double R = spec.curl_radius;
  switch (spec.shape)
  {
  case ChipMeshSpec::Shape::ribbon:
    return spec.length;
  case ChipMeshSpec::Shape::arc:
    return R * total_angle(spec);
  case ChipMeshSpec::Shape::helical:
    return spec.turns * std::hypot(two_pi * R, spec.pitch);
  case ChipMeshSpec::Shape::spiral:
    break;
  }
  return spiral_length(spec, 0, total_angle(spec));
}

double chip_volume(const ChipMeshSpec& spec)
{
  const double area = spec.width * spec.thickness;
  if (spec.shape == ChipMeshSpec::Shape::spiral)
  {
    // Radial offsets r +- w/2 in the plane: area = int r w dphi, r = R + b phi.
    const double phi = total_angle(spec), b = spec.pitch / two_pi;
    return area * (spec.curl_radius * phi + 0.5 * b * phi * phi);
  }
  // Straight, circular and Frenet-swept sections centred on the curve: the first moment
  // of the section about the curve vanishes, so the volume is the area times the length
  // (Pappus-Guldinus).
  return area * chip_centre_length(spec);
}

void check_chip_spec(const ChipMeshSpec& spec)
{
  auto positive = [](double v, const std::string& name)
  {
    if (!(v > 0) || !std::isfinite(v))
      throw InputError(name, "must be positive, got " + text(v));
  };
  positive(spec.width, "--width");
  positive(spec.thickness, "--thickness");
  positive(spec.size, "--size");
  if (spec.layers < 2)
    throw InputError("--layers", "at least 2 elements through the thickness, got " +
                                     std::to_string(spec.layers));
  if (spec.order != 1 && spec.order != 2)
    throw InputError("--order", "must be 1 or 2, got " + std::to_string(spec.order));
  const double w = spec.width, t = spec.thickness, R = spec.curl_radius;
  switch (spec.shape)
  {
  case ChipMeshSpec::Shape::ribbon:
    positive(spec.length, "--length");
    break;
  case ChipMeshSpec::Shape::arc:
    if (!(spec.arc_angle > 0) || spec.arc_angle > 360 + 1e-9)
      throw InputError("--arc-angle", "must lie in (0, 360] degrees (360: a closed ring; "
                                      "longer chips are --shape helical), got " +
                                          text(spec.arc_angle));
    break;
  case ChipMeshSpec::Shape::spiral:
  case ChipMeshSpec::Shape::helical:
    positive(spec.turns, "--turns");
    break;
  }
  if (spec.shape != ChipMeshSpec::Shape::ribbon && !(R > w / 2))
    throw InputError("--curl-radius", "must exceed half the width (" + text(w / 2) +
                                          " m): the inner edge would cross the curl axis, got " +
                                          text(R));
  if (spec.shape == ChipMeshSpec::Shape::spiral && !(spec.pitch > w))
    throw InputError("--pitch", "the spiral's radial pitch " + text(spec.pitch) +
                                    " m must exceed the width " + text(w) +
                                    " m, or adjacent turns overlap");
  if (spec.shape == ChipMeshSpec::Shape::helical)
  {
    if (!(spec.pitch >= 0))
      throw InputError("--pitch", "must not be negative, got " + text(spec.pitch));
    if (spec.turns >= 1)
    {
      // The Frenet-swept faces are ruled by horizontal lines passing the axis at the
      // distance d = t h / (2 s) (h = p / 2pi, s = sqrt(R^2 + h^2)). At the radius r a turn
      // spans t R / s + 2 h asin(d / r) along the axis; adjacent turns are one pitch
      // apart, so the chip is free of itself where this is below p at the inner edge.
      const double h = helix_rise(spec), s = std::hypot(R, h), d = t * h / (2 * s), r = R - w / 2;
      const double span =
          d < r ? t * R / s + 2 * h * std::asin(d / r) : std::numeric_limits<double>::infinity();
      if (!(spec.pitch > span))
        throw InputError("--pitch", "the helical chip intersects itself: a turn spans " +
                                        text(span) + " m along the axis, more than the pitch " +
                                        text(spec.pitch) + " m");
    }
  }
  const double length = chip_centre_length(spec);
  if (spec.size > length)
    throw InputError("--size", "mesh size " + text(spec.size) +
                                   " m is larger than the chip (centre-curve length " +
                                   text(length) + " m)");
  const double n_cells = std::ceil(length / spec.size) * std::ceil(w / spec.size) * spec.layers;
  if (n_cells > 2e6)
    throw InputError("--size", "too small for the chip (over 2 million hexahedra)");
}

ChipMeshSummary write_chip_mesh(const ChipMeshSpec& spec, const std::string& path)
{
  check_chip_spec(spec);
  ChipMeshSummary summary;
  with_gmsh_model(
      path,
      [&]
      {
        gmsh::model::add("chipflex_chip");
        const gmsh::vectorpair volumes = spec.shape == ChipMeshSpec::Shape::helical
                                             ? sweep_helical_chip(spec)
                                             : extrude_planar_chip(spec);
        // Construction points and the sweep path are not part of the chip.
        gmsh::vectorpair free_entities;
        for (int d = 0; d <= 2; ++d)
        {
          gmsh::vectorpair entities;
          gmsh::model::getEntities(entities, d);
          for (const auto& e : entities)
          {
            std::vector<int> up, down;
            gmsh::model::getAdjacencies(e.first, e.second, up, down);
            if (up.empty())
              free_entities.push_back(e);
          }
        }
        if (!free_entities.empty())
        {
          gmsh::model::occ::remove(free_entities, true);
          gmsh::model::occ::synchronize();
        }

        std::vector<int> volume_tags;
        for (const auto& v : volumes)
          volume_tags.push_back(v.second);
        gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, volume_tags), "body");
        const std::vector<int> skin = outer_faces(volumes);
        gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, skin), "skin");
        if (!chip_is_closed(spec))
        {
          const double end =
              spec.shape == ChipMeshSpec::Shape::ribbon ? spec.length : total_angle(spec);
          const double tolerance = 0.1 * std::min(spec.width, spec.thickness);
          gmsh::model::setPhysicalName(
              2, gmsh::model::addPhysicalGroup(2, {face_nearest(skin, centre(spec, 0), tolerance)}),
              "start");
          gmsh::model::setPhysicalName(
              2,
              gmsh::model::addPhysicalGroup(2, {face_nearest(skin, centre(spec, end), tolerance)}),
              "end");
        }

        gmsh::model::mesh::generate(3);
        if (spec.order == 2)
        {
          // Complete 27-node hexahedra, the nodes placed on the CAD surfaces.
          gmsh::option::setNumber("Mesh.SecondOrderIncomplete", 0);
          gmsh::model::mesh::setOrder(2);
        }
        if (spec.shape == ChipMeshSpec::Shape::helical || spec.shape == ChipMeshSpec::Shape::arc)
          snap_to_exact_chip(spec);
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> tags, nodes;
        gmsh::model::mesh::getElements(types, tags, nodes, 3);
        for (std::size_t k = 0; k < types.size(); ++k)
        {
          std::string name;
          int d, order, n_nodes, n_primary;
          std::vector<double> local;
          gmsh::model::mesh::getElementProperties(types[k], name, d, order, n_nodes, local,
                                                  n_primary);
          if (n_primary != 8)
            throw std::runtime_error("the chip mesh is not purely hexahedral (internal)");
          summary.n_elements += tags[k].size();
        }
        std::vector<std::size_t> node_tags;
        std::vector<double> coords, parametric;
        gmsh::model::mesh::getNodes(node_tags, coords, parametric);
        summary.n_nodes = node_tags.size();

        write_mesh_file(path);
      });
  return summary;
}
} // namespace chipflex::meshes
