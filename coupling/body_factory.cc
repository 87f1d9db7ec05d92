#include "coupling/body_factory.h"

#include "common/input_error.h"
#include "common/reduced_body_file.h"
#include "coupling/fmu_body.h"
#include "coupling/large_rotation_beam_skin.h"
#include "coupling/multibody_coupled_body.h"
#include "coupling/sph_solid_body.h"
#include "mbs/composite_skin.h"
#include "mbs/joint.h"
#include "mbs/rigid_body.h"
#include "mbs/rigid_chain.h"

#include <cmath>

namespace chipflex::coupling
{
using Vector = Eigen::Vector2d;

BodyKind parse_body_kind(const std::string& word, const std::string& where)
{
  if (word == "rigid")
    return BodyKind::rigid;
  if (word == "chain")
    return BodyKind::chain;
  if (word == "flexible")
    return BodyKind::flexible;
  if (word == "sph solid" || word == "sph-solid")
    return BodyKind::sph_solid;
  if (word == "fmu")
    return BodyKind::fmu;
  throw InputError(where, "unknown body kind '" + word +
                              "' (expected rigid, chain, flexible, sph solid or fmu)");
}

std::string to_string(BodyKind kind)
{
  switch (kind)
  {
  case BodyKind::rigid:
    return "rigid";
  case BodyKind::chain:
    return "chain";
  case BodyKind::flexible:
    return "flexible";
  case BodyKind::sph_solid:
    return "sph-solid";
  case BodyKind::fmu:
    return "fmu";
  }
  return "?";
}

namespace
{
void require_positive(double value, const std::string& body, const std::string& key)
{
  if (!(value > 0))
    throw InputError("body '" + body + "', " + key,
                     "must be positive, got " + std::to_string(value));
}

std::unique_ptr<mbs::MultibodySystem<2>> make_system(const BodyDescription& d,
                                                     const Vector& gravity)
{
  mbs::IntegratorOptions options;
  options.scheme = d.implicit ? mbs::IntegratorOptions::Scheme::generalized_alpha
                              : mbs::IntegratorOptions::Scheme::symplectic_euler;
  if (!(d.rho_infinity >= 0 && d.rho_infinity <= 1))
    throw InputError("body '" + d.name + "', rho infinity",
                     "must lie in [0, 1], got " + std::to_string(d.rho_infinity));
  options.rho_infinity = d.rho_infinity;
  auto system = std::make_unique<mbs::MultibodySystem<2>>(options);
  system->set_gravity(gravity);
  return system;
}

std::unique_ptr<CoupledBody<2>> make_rigid(const BodyDescription& d, const Vector& gravity)
{
  require_positive(d.width, d.name, "width");
  require_positive(d.height, d.name, "height");
  require_positive(d.density, d.name, "density");
  const double w = d.width, h = d.height, mass = d.density * w * h;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  inertia(2, 2) = mass * (w * w + h * h) / 12;
  // Counter-clockwise outline, nodes every ~ min(w, h)/4 so that the fluid's reaction
  // is resolved along the faces (the wall force acts per face either way).
  std::vector<Vector> nodes;
  const int nw = std::max(1, int(std::ceil(4 * w / std::min(w, h))));
  const int nh = std::max(1, int(std::ceil(4 * h / std::min(w, h))));
  const Vector corner[4] = {{-w / 2, -h / 2}, {w / 2, -h / 2}, {w / 2, h / 2}, {-w / 2, h / 2}};
  for (int side = 0; side < 4; ++side)
  {
    const int n = side % 2 == 0 ? nw : nh;
    for (int k = 0; k < n; ++k)
      nodes.push_back(corner[side] + (corner[(side + 1) % 4] - corner[side]) * double(k) / n);
  }
  std::vector<std::array<int, 2>> faces;
  for (int k = 0; k < int(nodes.size()); ++k)
    faces.push_back({k, (k + 1) % int(nodes.size())});
  auto system = make_system(d, gravity);
  auto body =
      mbs::make_rigid_body<2>(mbs::rigid_body_data<2>(mass, Vector::Zero(), inertia, nodes, faces));
  body->set_pose(d.position, d.angle);
  body->set_frame_velocity(d.velocity, Eigen::Matrix<double, 1, 1>::Zero());
  if (d.clamped)
    body->clamp_to_ground();
  auto* skin = body.get();
  system->add_body(std::move(body));
  return std::make_unique<MultibodyCoupledBody<2>>("rigid", std::move(system), *skin, d.max_step,
                                                   [](const mbs::MultibodySystem<2>& s)
                                                   { return Vector(s.body(0).position()); });
}

std::unique_ptr<CoupledBody<2>> make_chain(const BodyDescription& d, const Vector& gravity)
{
  if (d.links < 1 || d.links > 3)
    throw InputError("body '" + d.name + "', links",
                     "the seed's chains have 1, 2 or 3 links, got " + std::to_string(d.links));
  auto gate = mbs::RigidChainGate::seed_table2(d.links);
  gate.total_length = d.length;
  gate.thickness = d.thickness;
  gate.density = d.density;
  if (d.spring_rate > 0)
    gate.spring_rate = d.spring_rate;
  gate.spring_damping = d.spring_damping;
  gate.clamp_point = d.position;
  require_positive(gate.total_length, d.name, "length");
  require_positive(gate.thickness, d.name, "thickness");
  auto system = make_system(d, gravity);
  const mbs::RigidChain chain = mbs::add_rigid_chain(*system, gate);
  std::vector<mbs::FloatingFrameBody<2>*> links;
  for (int l : chain.links)
    links.push_back(&system->body(l));
  auto skin = std::make_unique<mbs::CompositeSkin<2>>(links);
  return std::make_unique<MultibodyCoupledBody<2>>(
      "chain", std::move(system), std::move(skin), d.max_step,
      [chain](const mbs::MultibodySystem<2>& s) { return chain.tip_position(s); });
}

std::unique_ptr<CoupledBody<2>> make_flexible(const BodyDescription& d, const Vector& gravity)
{
  if (d.body_file.empty())
    throw InputError("body '" + d.name + "', body file",
                     "a flexible body needs a body file from `chipflex reduce`");
  const ReducedBodyData data = read_reduced_body(d.body_file);
  if (data.dim != 2)
    throw InputError(d.body_file, "a " + std::to_string(data.dim) + "D body file in a 2D case");
  if (d.modes == 0 || d.modes > data.n_modes())
    throw InputError("body '" + d.name + "', modes",
                     "the file has " + std::to_string(data.n_modes()) + " modes, asked for " +
                         std::to_string(d.modes));
  mbs::FloatingFrameOptions options;
  options.n_modes = d.modes;
  if (d.modal_damping > 0 && (d.rayleigh_mass > 0 || d.rayleigh_stiffness > 0))
    throw InputError("body '" + d.name + "', damping",
                     "give either a modal damping ratio or Rayleigh coefficients, not both");
  if (d.modal_damping > 0)
  {
    options.damping = mbs::DampingKind::modal;
    options.modal_damping_ratio = d.modal_damping;
  }
  else if (d.rayleigh_mass > 0 || d.rayleigh_stiffness > 0)
  {
    options.damping = mbs::DampingKind::rayleigh;
    options.rayleigh_mass = d.rayleigh_mass;
    options.rayleigh_stiffness = d.rayleigh_stiffness;
  }
  auto system = make_system(d, gravity);
  auto body = std::make_unique<mbs::FloatingFrameBody<2>>(data, options);
  const std::vector<int> probe = body->node_set(d.probe_set); // InputError if missing
  body->set_pose(d.position, d.angle);
  body->set_frame_velocity(d.velocity, Eigen::Matrix<double, 1, 1>::Zero());
  if (d.clamped)
    body->clamp_to_ground();
  auto* skin = body.get();
  system->add_body(std::move(body));
  if (d.large_rotation)
  {
    if (!d.clamped)
      throw InputError("body '" + d.name + "', large rotation", "needs a clamped body");
    auto beam = std::make_unique<LargeRotationBeamSkin>(*skin, d.clamp_set, d.probe_set);
    const LargeRotationBeamSkin* probe_skin = beam.get();
    return std::make_unique<MultibodyCoupledBody<2>>(
        "flexible", std::move(system), std::move(beam), d.max_step,
        [probe_skin](const mbs::MultibodySystem<2>&) { return probe_skin->tip_position(); });
  }
  return std::make_unique<MultibodyCoupledBody<2>>("flexible", std::move(system), *skin, d.max_step,
                                                   [probe](const mbs::MultibodySystem<2>& s)
                                                   {
                                                     Vector sum = Vector::Zero();
                                                     for (int n : probe)
                                                       sum += s.body(0).node_position(n);
                                                     return Vector(sum / double(probe.size()));
                                                   });
}

std::unique_ptr<CoupledBody<2>> make_sph_solid(const BodyDescription& d, const Vector& gravity)
{
  require_positive(d.solid_spacing, d.name, "spacing");
  require_positive(d.solid.density, d.name, "density");
  require_positive(d.solid.youngs_modulus, d.name, "youngs modulus");
  if (!(d.solid.poisson_ratio > -1 && d.solid.poisson_ratio < 0.5))
    throw InputError("body '" + d.name + "', poisson ratio",
                     "must lie in (-1, 0.5), got " + std::to_string(d.solid.poisson_ratio));
  if (d.solid_layers < 2 || d.clamp_columns < d.solid_layers || d.clamp_rows < 1)
    throw InputError("body '" + d.name + "', layers",
                     "need at least 2 layers and a clamp at least as wide as the strip");
  sph::SolidStripLayout layout;
  layout.clamped_end_centre = d.position;
  layout.direction = d.direction;
  layout.length = d.length;
  layout.thickness = d.thickness;
  layout.spacing = d.solid_spacing;
  layout.layers = d.solid_layers;
  layout.clamp_rows = d.clamp_rows;
  layout.clamp_columns = d.clamp_columns;
  return std::make_unique<SphSolidBody>(d.solid, layout, d.smoothing_factor, gravity);
}
} // namespace

std::unique_ptr<CoupledBody<2>> make_coupled_body(const BodyDescription& d, const Vector& gravity)
{
  switch (d.kind)
  {
  case BodyKind::rigid:
    return make_rigid(d, gravity);
  case BodyKind::chain:
    return make_chain(d, gravity);
  case BodyKind::flexible:
    return make_flexible(d, gravity);
  case BodyKind::sph_solid:
    return make_sph_solid(d, gravity);
  case BodyKind::fmu:
    return make_fmu_body(d, gravity);
  }
  throw std::logic_error("make_coupled_body: unknown kind");
}
} // namespace chipflex::coupling
