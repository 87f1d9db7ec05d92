// The SPH solid gate model (Gray, Monaghan & Swift 2001) and its skin.
// References: Euler-Bernoulli first bending frequency of a clamped strip in plane
// strain, f1 = 1.8751^2 / (2 pi L^2) sqrt(E t^2 / (12 rho (1 - nu^2))); and the
// momentum balance d/dt (sum m v + clamp impulse) = sum of the skin forces.

#include "coupling/sph_solid_body.h"

#include <catch2/catch.hpp>
#include <cmath>

using chipflex::coupling::SphSolidBody;
using Vector = Eigen::Vector2d;

namespace
{
Vector tip(const SphSolidBody& body)
{
  std::vector<Vector> x;
  body.skin_positions(x);
  Vector sum = Vector::Zero();
  for (int k : body.skin_map().tip_nodes)
    sum += x[k];
  return sum / body.skin_map().tip_nodes.size();
}
} // namespace

TEST_CASE("SPH solid skin sits half a spacing outside the particles", "[coupling]")
{
  chipflex::sph::SolidStripLayout layout; // the Antoci gate, Table 1
  layout.clamped_end_centre = Vector(0.1025, 0.079);
  SphSolidBody body(chipflex::sph::SolidMaterial{}, layout, 1.3, Vector::Zero());
  CHECK(body.solid().n_particles() == 79 * 6 + 8 * 4);
  std::vector<Vector> x;
  body.skin_positions(x);
  double x_min = 1, x_max = 0, y_min = 1;
  for (const auto& p : x)
  {
    x_min = std::min(x_min, p.x());
    x_max = std::max(x_max, p.x());
    y_min = std::min(y_min, p.y());
  }
  CHECK(x_min == Approx(0.100).margin(1e-12));
  CHECK(x_max == Approx(0.105).margin(1e-12));
  CHECK(y_min == Approx(0.0).margin(1e-12));
  CHECK(tip(body).x() == Approx(0.1025).margin(1e-12));
  // Outward normals (dy, -dx): the first face is on the fluid (left) side.
  const auto& f = body.skin_faces().front();
  const Vector d = x[f[1]] - x[f[0]];
  CHECK(d.y() < 0);
  CHECK(Vector(d.y(), -d.x()).x() < 0);
}

TEST_CASE("SPH solid: skin forces change momentum by exactly their impulse", "[coupling]")
{
  chipflex::sph::SolidStripLayout layout;
  layout.spacing = 2e-3;
  layout.layers = 3;
  layout.clamp_columns = 5;
  layout.clamp_rows = 2;
  SphSolidBody body(chipflex::sph::SolidMaterial{}, layout, 1.3, Vector::Zero());
  std::vector<Vector> f(body.n_skin_nodes());
  Vector total = Vector::Zero();
  for (std::size_t k = 0; k < f.size(); ++k)
  {
    f[k] = Vector(std::sin(1.0 + k), std::cos(3.0 * k)) * 10.0;
    total += f[k];
  }
  body.set_skin_forces(f);
  const Vector p0 = body.linear_momentum();
  const double dt = 2e-4;
  body.advance(dt);
  const Vector dp = body.linear_momentum() - p0;
  CHECK((dp - total * dt).norm() <= 1e-12 * total.norm() * dt + 1e-15);
  CHECK(body.substeps() > 1);
}
