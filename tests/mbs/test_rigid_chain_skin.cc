// The rigid-chain gate's skin stays closed at its hinges. A flat link end that turns about
// the middle of its edge opens a wedge under the wall it hangs from (and against the next
// link); at dp 1 mm the elastic-gate fluid entered that wedge and was squeezed out at up to
// 13 m/s. With rounded hinge ends every point where the fluid's boundary meets the link
// (the wall's corners, the neighbour link's corners) stays on or inside the link's outline.
#include "elastic_gate_chain.h"
#include "mbs/multibody_system.h"
#include "mbs/rigid_body.h"
#include "mbs/rigid_chain.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

using namespace chipflex;
using namespace chipflex::mbs;

namespace
{
using Point = Eigen::Vector2d;

/// How far p lies outside the closed polygon (0 inside): even-odd rule, then the distance
/// to the nearest edge.
double distance_outside(const std::vector<Point>& polygon, const Point& p)
{
  bool inside = false;
  double d = INFINITY;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++)
  {
    const Point& a = polygon[j];
    const Point& b = polygon[i];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      inside = !inside;
    const Point ab = b - a;
    const double s = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    d = std::min(d, (a + s * ab - p).norm());
  }
  return inside ? 0.0 : d;
}

struct PosedChain
{
  MultibodySystem<2> system;
  RigidChain chain;
  std::vector<std::vector<Point>> skins; ///< world outline of every link

  PosedChain(const RigidChainSpec& gate, const std::vector<double>& angles)
  {
    chain = add_rigid_chain(system, gate);
    Point hinge = gate.clamp_point;
    for (std::size_t i = 0; i < chain.links.size(); ++i)
    {
      auto& link = system.body(chain.links[i]);
      link.set_pose(hinge, angles[i]);
      std::vector<Point> x;
      link.skin_positions(x);
      skins.push_back(x);
      hinge = link.point_position(Point(0.0, -chain.link_length));
    }
  }
};

/// The largest gap, over the links' turns, between a link's outline and the corners that
/// close the fluid's boundary at its hinges: the wall's bottom corners at the clamp
/// (clamp_point +- (h, 0)), and each neighbour link's corners at a joint.
double largest_hinge_gap(const RigidChainSpec& gate)
{
  const double h = 0.5 * gate.thickness;
  double gap = 0;
  for (double a0 : {-0.8, -0.3, 0.2, 0.7})
    for (double da : {-0.6, 0.0, 0.5})
    {
      std::vector<double> angles(gate.n_links);
      for (int i = 0; i < gate.n_links; ++i)
        angles[i] = a0 + i * da;
      const PosedChain c(gate, angles);
      for (double side : {-h, h})
        gap = std::max(gap, distance_outside(c.skins[0], gate.clamp_point + Point(side, 0.0)));
      for (int i = 0; i + 1 < gate.n_links; ++i)
      {
        const auto& upper = c.system.body(c.chain.links[i]);
        const auto& lower = c.system.body(c.chain.links[i + 1]);
        for (double side : {-h, h})
        {
          const double l = c.chain.link_length;
          gap = std::max(gap,
                         distance_outside(c.skins[i + 1], upper.point_position(Point(side, -l))));
          gap = std::max(gap, distance_outside(c.skins[i], lower.point_position(Point(side, 0))));
        }
      }
    }
  return gap;
}
} // namespace

TEST_CASE("Rounded hinge ends keep the chain gate's skin closed at every angle",
          "[mbs][rigid][chain]")
{
  for (int links : {1, 2, 3})
  {
    RigidChainSpec gate = testing::elastic_gate_chain(links);
    gate.clamp_point = Point(0.1025, 0.079);
    const double h = 0.5 * gate.thickness;
    // The gap the polygonal half circle leaves: its sag h (1 - cos(pi / 16)) at 8 segments.
    const double sag = h * (1 - std::cos(M_PI / 16));
    INFO(links << " link(s)");
    CHECK(largest_hinge_gap(gate) <= sag + 1e-12);
    // Flat ends open the wedge: h sin(0.8 rad) = 1.8 mm at the clamp.
    gate.rounded_hinges = false;
    CHECK(largest_hinge_gap(gate) > 0.5 * h);
  }
}

TEST_CASE("A rounded link keeps the rectangle's mass, inertia and corner node sets",
          "[mbs][rigid][chain]")
{
  const double l = 0.0395, t = 0.005, rho = 1100;
  const ReducedBodyData flat = rectangular_link_data(l, t, rho);
  LinkEnds ends;
  ends.round_top = ends.round_bottom = true;
  const ReducedBodyData round = rectangular_link_data(l, t, rho, ends);
  CHECK(round.mass == flat.mass);
  CHECK(round.inertia_tensor(2, 2) == flat.inertia_tensor(2, 2));
  CHECK(flat.nodes.rows() == 4);
  CHECK(round.nodes.rows() == 4 + 2 * (ends.arc_segments - 1));
  CHECK(round.skin_faces.rows() == round.nodes.rows());
  const auto corner = [&](const ReducedBodyData& d, const std::string& set, int k)
  { return Point(d.nodes.row(d.node_sets.at(set)[k]).transpose()); };
  for (int k : {0, 1})
  {
    CHECK((corner(round, "tip", k) - corner(flat, "tip", k)).norm() == 0.0);
    CHECK((corner(round, "clamp", k) - corner(flat, "clamp", k)).norm() == 0.0);
  }
  // The half circles bulge outward, to y = +t/2 and -l - t/2, and the outline stays
  // counter-clockwise (positive signed area: the rectangle plus two polygonal half discs).
  CHECK(round.nodes.col(1).maxCoeff() == Approx(0.5 * t).epsilon(1e-12));
  CHECK(round.nodes.col(1).minCoeff() == Approx(-l - 0.5 * t).epsilon(1e-12));
  double area = 0;
  for (int f = 0; f < round.skin_faces.rows(); ++f)
  {
    const Point a = round.nodes.row(round.skin_faces(f, 0)).transpose();
    const Point b = round.nodes.row(round.skin_faces(f, 1)).transpose();
    area += 0.5 * (a.x() * b.y() - a.y() * b.x());
  }
  const double half_disc = 0.5 * 16 * 0.125 * t * t * std::sin(M_PI / 8); // 8 of 16 triangles
  CHECK(area == Approx(l * t + 2 * half_disc).epsilon(1e-12));
}
