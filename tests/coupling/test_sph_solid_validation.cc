// The SPH solid gate model (the default: total Lagrangian, St Venant-Kirchhoff, Bonet & Lok
// 1999 corrected kernel gradients, Ganzenmueller 2015 hourglass control alpha = 10) against
// beam theory, clamped strip in plane strain (E' = E / (1 - nu^2), I = t^3 / 12 per metre),
// Euler-Bernoulli:
//   first bending frequency  f1 = 1.8751^2 / (2 pi L^2) sqrt(E' I / (rho t)),
//   tip deflection under a uniform load q: w = q L^4 / (8 E' I);
// Timoshenko's shear and rotary inertia move these by +0.5 % (deflection) and -0.3 %
// (frequency) at the gate's t / L = 0.063, a tenth of the band; and, at the gate's range of
// deflection, the elastica under a tip load.
// About a minute (58 s of CPU for both cases): CTest label `validation`.
//
// Why 5 % either way: the seed's GMS-2001 solid (`formulation = updated lagrangian`) is
// 8 % low in frequency and 26 % soft in deflection at these six layers; the corrected total
// Lagrangian solid without hourglass control 15 % low and 38 % soft; with alpha = 50 30 %
// high and 41 % stiff; plane stress would be 8 % low and 19 % soft (docs/sph.md). Each
// fails, so does a factor of two.

#include "coupling/sph_solid_body.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

using chipflex::coupling::SphSolidBody;
using Vector = Eigen::Vector2d;

namespace
{
/// The elastic gate's rubber (Antoci et al. 2007, Table 1); the material has no defaults.
chipflex::sph::SolidMaterial table1_rubber()
{
  chipflex::sph::SolidMaterial m;
  m.density = 1100;
  m.youngs_modulus = 1.2e7;
  m.poisson_ratio = 0.4;
  return m;
}

/// Downward crossings of `level` in the sampled history (linear interpolation).
std::vector<double> downward_crossings(const std::vector<double>& t, const std::vector<double>& w,
                                       double level)
{
  std::vector<double> c;
  for (std::size_t k = 1; k < w.size(); ++k)
    if (w[k - 1] > level && w[k] <= level)
      c.push_back(t[k - 1] + (t[k] - t[k - 1]) * (w[k - 1] - level) / (w[k - 1] - w[k]));
  return c;
}

/// The Table 1 strip as a horizontal cantilever without gravity.
struct HorizontalStrip
{
  chipflex::sph::SolidMaterial material = table1_rubber();
  chipflex::sph::SolidStripLayout layout = horizontal();
  SphSolidBody body{material, layout, 1.3, Vector::Zero()};

  /// E' I per metre in plane strain.
  double bending_stiffness() const
  {
    const double t = layout.thickness, nu = material.poisson_ratio;
    return material.youngs_modulus / (1 - nu * nu) * t * t * t / 12;
  }

  static chipflex::sph::SolidStripLayout horizontal()
  {
    chipflex::sph::SolidStripLayout l; // the elastic gate's strip (Table 1)
    l.length = 0.079;
    l.thickness = 0.005;
    l.direction = Vector(1, 0);
    return l;
  }
};

/// Ramps the skin forces `full` in linearly over `ramp` seconds, holds them until `end`,
/// and calls sample(time) after every step past the ramp.
template <class Sample>
void ramp_and_hold(SphSolidBody& body, const std::vector<Vector>& full, double ramp, double end,
                   double dt, Sample sample)
{
  double time = 0;
  while (time < end)
  {
    const double scale = std::min(1.0, (time + 0.5 * dt) / ramp);
    std::vector<Vector> f(full);
    for (auto& fk : f)
      fk *= scale;
    body.set_skin_forces(f);
    body.advance(dt);
    time += dt;
    if (time > ramp)
      sample(time);
  }
}
} // namespace

TEST_CASE("SPH solid gate: stiffness in frequency and statics against Euler-Bernoulli",
          "[coupling][validation]")
{
  HorizontalStrip strip;
  SphSolidBody& body = strip.body;
  const double L = strip.layout.length, t = strip.layout.thickness, rho = strip.material.density;
  const double EI = strip.bending_stiffness();
  const double f_beam = 1.8751 * 1.8751 / (2 * M_PI * L * L) * std::sqrt(EI / (rho * t));
  const double q = 6;                                  // N/m, downward on the upper face
  const double w_beam = q * std::pow(L, 4) / (8 * EI); // 0.20 mm: linear range

  // The load on the upper side's faces (skin nodes above the centre line), lumped onto
  // their end nodes by face length.
  std::vector<Vector> x, f_full(body.n_skin_nodes(), Vector::Zero());
  body.skin_positions(x);
  for (const auto& face : body.skin_faces())
  {
    const Vector a = x[face[0]], b = x[face[1]];
    if (a.y() > 0 && b.y() > 0)
    {
      const double half = 0.5 * q * std::abs(b.x() - a.x());
      f_full[face[0]].y() -= half;
      f_full[face[1]].y() -= half;
    }
  }
  // Ramp the load over 1.5 beam periods: it leaves a free first-mode oscillation of about
  // a fifth of the deflection, whose period is the frequency and whose mean over whole
  // periods is the static deflection.
  const double y0 = body.probe_position().y(), ramp = 1.5 / f_beam, dt = 1e-4;
  std::vector<double> times, w;
  ramp_and_hold(body, f_full, ramp, ramp + 3.6 / f_beam, dt,
                [&](double time)
                {
                  times.push_back(time);
                  w.push_back(y0 - body.probe_position().y());
                });
  const auto [lo, hi] = std::minmax_element(w.begin(), w.end());
  const std::vector<double> rough = downward_crossings(times, w, 0.5 * (*lo + *hi));
  REQUIRE(rough.size() >= 3);
  const double period = (rough.back() - rough.front()) / double(rough.size() - 1);
  double sum = 0;
  int n = 0;
  for (std::size_t k = 0; k < times.size(); ++k)
    if (times[k] >= rough.front() && times[k] < rough.back())
    {
      sum += w[k];
      ++n;
    }
  const double w_sph = sum / n, f_sph = 1 / period;
  INFO("frequency: SPH " << f_sph << " Hz, beam " << f_beam << " Hz; tip deflection: SPH "
                         << w_sph * 1e3 << " mm, beam " << w_beam * 1e3 << " mm");
  // Measured: 14.50 Hz against 14.75 Hz (-1.7 %), 0.2027 mm against 0.1963 mm (+3.3 %).
  CHECK(f_sph == Approx(f_beam).epsilon(0.05));
  CHECK(w_sph == Approx(w_beam).epsilon(0.05));
  // A linear structure whose static shape is almost its first mode: the compliance ratio
  // is about the squared frequency ratio (measured 1.033 against 1.035).
  CHECK(w_sph / w_beam == Approx(std::pow(f_beam / f_sph, 2)).epsilon(0.05));
}

TEST_CASE("SPH solid gate: large deflection under a tip load against the elastica",
          "[coupling][validation]")
{
  // A dead tip load P = alpha EI / L^2 normal to the axis with alpha = 2 bends the strip
  // as far as the flow bends the gate (tip 39 mm across). Elastica (Mattiasson 1981,
  // Table 1): the tip moves 0.4935 L across and 0.1606 L back along the axis.
  HorizontalStrip strip;
  SphSolidBody& body = strip.body;
  const double L = strip.layout.length;
  const double alpha = 2, P = alpha * strip.bending_stiffness() / (L * L);
  const auto& tip_nodes = body.skin_map().tip_nodes;
  std::vector<Vector> f_full(body.n_skin_nodes(), Vector::Zero());
  for (int k : tip_nodes)
    f_full[k].y() = -P / double(tip_nodes.size());
  // Ramp over about two periods, then average over about two more: the mean of what is
  // left of the oscillation is within about 1 % of the static deflection.
  const Vector p0 = body.probe_position();
  const double period = 0.075, ramp = 2 * period, dt = 1e-4;
  double across = 0, back = 0;
  int n = 0;
  ramp_and_hold(body, f_full, ramp, ramp + 2 * period, dt,
                [&](double)
                {
                  const Vector d = body.probe_position() - p0;
                  across -= d.y() / L;
                  back -= d.x() / L;
                  ++n;
                });
  across /= n;
  back /= n;
  INFO("tip / L: across " << across << " (elastica 0.4935), back " << back << " (elastica 0.1606)");
  // Measured: 0.5069 across (+2.7 %) and 0.1706 back (+6.3 %; the seed's GMS-2001 solid:
  // 0.616 and 0.252, 25 % and 57 % beyond). Bands: 5 % across, 10 % back, either way.
  CHECK(across == Approx(0.4935).epsilon(0.05));
  CHECK(back == Approx(0.1606).epsilon(0.10));
}
