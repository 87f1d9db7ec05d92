// Rigid shapes (coupling/rigid_shapes.h): the primitives' skins are closed, outward and
// enclose (nearly) the solid whose exact mass properties they carry; the divergence-
// theorem mass properties of a closed surface are exact for polyhedra. References:
// the textbook volumes and moments of inertia of a box (m (b^2 + c^2) / 12), a solid
// cylinder (m r^2 / 2 about its axis, m (3 r^2 + L^2) / 12 across) and a sphere
// (2 m r^2 / 5).

#include "common/input_error.h"
#include "coupling/fluid_overlap.h"
#include "coupling/rigid_shapes.h"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

using namespace chipflex;
using Eigen::Vector2d;
using Eigen::Vector3d;

TEST_CASE("a closed box surface, shifted and rotated, gets the box's exact mass properties")
{
  const auto box = coupling::box_shape<3>(Vector3d(0.3, 0.2, 0.1), 800, 0.04);
  // Move the skin off the origin and turn it: the divergence theorem must give the same
  // volume and inertia about the centre (rotated), and the shifted centre.
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Vector3d shift(1.0, -2.0, 0.5);
  std::vector<Vector3d> nodes;
  for (const auto& x : box.nodes)
    nodes.push_back(shift + r * x);
  const auto s = coupling::closed_surface_shape<3>(nodes, box.faces, 800, "box");
  CHECK(s.volume == Approx(0.3 * 0.2 * 0.1).epsilon(1e-12));
  CHECK(s.mass == Approx(box.mass).epsilon(1e-12));
  CHECK((s.centre_of_mass - shift).norm() < 1e-12);
  const Eigen::Matrix3d expected = r * box.inertia * r.transpose();
  // The shift costs digits: the moments about the origin are ~100 times those about
  // the centre (parallel axes).
  CHECK((s.inertia - expected).norm() < 1e-9 * expected.norm());
}

TEST_CASE("inward faces are flipped, an open surface is refused")
{
  auto box = coupling::box_shape<3>(Vector3d(1, 1, 1), 1000, 0.5);
  auto inward = box.faces;
  for (auto& f : inward)
    std::swap(f[1], f[2]);
  const auto s = coupling::closed_surface_shape<3>(box.nodes, inward, 1000, "inward");
  CHECK(s.volume == Approx(1.0).epsilon(1e-12));
  for (std::size_t k = 0; k < s.faces.size(); ++k)
    CHECK(s.faces[k] == box.faces[k]);
  auto open = box.faces;
  open.pop_back();
  CHECK_THROWS_AS(coupling::closed_surface_shape<3>(box.nodes, open, 1000, "open"), InputError);
}

TEST_CASE("sphere and cylinder skins are closed, outward and close to the solid")
{
  // Inscribed polyhedra: their volume falls short of the solid's by O(spacing^2 / r^2).
  const double r = 0.05, spacing = 0.005;
  const auto sphere = coupling::sphere_shape<3>(r, 1000, spacing);
  const auto faceted =
      coupling::closed_surface_shape<3>(sphere.nodes, sphere.faces, 1000, "sphere");
  CHECK(sphere.volume == Approx(4.0 / 3 * M_PI * r * r * r).epsilon(1e-12));
  CHECK(sphere.inertia(0, 0) == Approx(0.4 * sphere.mass * r * r).epsilon(1e-12));
  CHECK(faceted.volume < sphere.volume);
  CHECK(faceted.volume == Approx(sphere.volume).epsilon(0.02));
  CHECK(faceted.centre_of_mass.norm() < 1e-12);
  for (std::size_t k = 0; k < faceted.faces.size(); ++k) // nothing needed flipping
    CHECK(faceted.faces[k] == sphere.faces[k]);

  const auto cylinder = coupling::cylinder_shape<3>(r, 0.2, 1000, spacing);
  const auto c =
      coupling::closed_surface_shape<3>(cylinder.nodes, cylinder.faces, 1000, "cylinder");
  CHECK(cylinder.inertia(2, 2) == Approx(0.5 * cylinder.mass * r * r).epsilon(1e-12));
  CHECK(cylinder.inertia(0, 0) == Approx(cylinder.mass * (3 * r * r + 0.04) / 12).epsilon(1e-12));
  CHECK(c.volume == Approx(cylinder.volume).epsilon(0.01));
  CHECK(c.inertia(2, 2) == Approx(cylinder.inertia(2, 2)).epsilon(0.02));
}

TEST_CASE("2D outlines: a rectangle's exact area and polar moment, a disc's close")
{
  const auto rect = coupling::box_shape<2>(Vector2d(0.4, 0.1), 500, 0.01);
  std::vector<Vector2d> shifted;
  for (const auto& x : rect.nodes)
    shifted.push_back(x + Vector2d(3, 4));
  const auto s = coupling::closed_surface_shape<2>(shifted, rect.faces, 500, "rectangle");
  CHECK(s.volume == Approx(0.04).epsilon(1e-12));
  CHECK((s.centre_of_mass - Vector2d(3, 4)).norm() < 1e-12);
  CHECK(s.inertia(2, 2) == Approx(rect.mass * (0.16 + 0.01) / 12).epsilon(1e-9));
  const auto disc = coupling::sphere_shape<2>(0.1, 500, 0.005);
  const auto d = coupling::closed_surface_shape<2>(disc.nodes, disc.faces, 500, "disc");
  CHECK(d.volume == Approx(M_PI * 0.01).epsilon(0.005));
  CHECK(d.inertia(2, 2) == Approx(disc.inertia(2, 2)).epsilon(0.01));
}

TEST_CASE("fluid overlapping a skin: inside a closed skin or within the margin of a face")
{
  const auto box = coupling::box_shape<3>(Vector3d(0.06, 0.01, 0.06), 1000, 0.03);
  std::vector<Vector3d> nodes;
  for (const auto& x : box.nodes)
    nodes.push_back(x + Vector3d(0.15, 0.1, 0.03));
  const coupling::SkinOverlap<3> overlap(nodes, box.faces, 0.004);
  CHECK(overlap.closed());
  CHECK(overlap(Vector3d(0.15, 0.1, 0.03)));   // centre
  CHECK(overlap(Vector3d(0.13, 0.095, 0.02))); // on a face
  CHECK(overlap(Vector3d(0.13, 0.092, 0.02))); // 3 mm in front of it
  CHECK(!overlap(Vector3d(0.13, 0.09, 0.02))); // 5 mm in front of it
  CHECK(!overlap(Vector3d(0.5, 0.5, 0.5)));    // far
  CHECK(overlap(Vector3d(0.175, 0.1, 0.055))); // inside, near a corner
  CHECK(!overlap(Vector3d(0.19, 0.1, 0.03)));  // 1 cm beside
  const auto disc = coupling::sphere_shape<2>(0.05, 1000, 0.01);
  const coupling::SkinOverlap<2> in_2d(disc.nodes, disc.faces, 0.002);
  CHECK(in_2d.closed());
  CHECK(in_2d(Vector2d(0.0, 0.03)));
  CHECK(!in_2d(Vector2d(0.0, 0.06)));
}
