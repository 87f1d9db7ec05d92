// Body kind `fe`: the full geometrically nonlinear FE model of a mesh (fem/fe_body_model.h:
// total Lagrangian, St Venant-Kirchhoff or neo-Hooke, generalised-alpha with Newton), 2D or
// 3D, clamped on a boundary group or free, coupled through its skin nodes: the fluid's
// forces on the skin are nodal forces of the FE model, the skin's positions and velocities
// are the FE nodes'. The reference against which a reduced body is judged in the flow.
//
// Time steps. `fe time step` = 0 takes one FE step per fluid step (or `max step` sub-steps)
// with the skin forces held over it, as the mbs kinds do. An FE step costs a few sparse
// factorisations, so with `fe time step` = D > 0 the FE model steps on its own grid
// 0, D, 2D, ... and the fluid sub-cycles inside each FE step: the step T -> T + D is taken
// when the fluid reaches T, under the mean skin force of the fluid's steps in [T - D, T]
// (the first one, before any such window, under the forces of the first fluid step), so
// the body receives the fluid's impulse one FE step late. Meanwhile the skin moves on the cubic
// Hermite curve through the FE states (u, v) at T and T + D: positions continuous and velocities
// continuous across FE steps, the velocity the curve's derivative.

#include "apps/body_kinds/body_kind.h"
#include "common/input_error.h"
#include "fem/fe_body_model.h"

#include <algorithm>
#include <cmath>

namespace chipflex::apps
{
namespace
{
template <int dim>
class FeCoupledBody : public coupling::CoupledBody<dim>, public mbs::SkinBody<dim>
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  using Matrix = Eigen::Matrix<double, dim, dim>;

  FeCoupledBody(std::unique_ptr<fem::FeBodyModel<dim>> model, const BodyPlacement<dim>& placement,
                const Vector& gravity, double fe_step, double max_step, std::vector<int> probe)
      : model_(std::move(model)), rotation_(placement.rotation), origin_(placement.position),
        fe_step_(fe_step), max_step_(max_step), probe_(std::move(probe))
  {
    const auto& nodes = model_->skin_nodes();
    std::vector<int> skin_index(model_->n_nodes(), -1);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      skin_index[nodes[i]] = int(i);
    for (auto face : model_->skin_faces())
    {
      for (auto& n : face)
        n = skin_index[n];
      faces_.push_back(face);
    }
    const int n = model_->n_nodes() * dim;
    gravity_force_ = Eigen::VectorXd::Zero(n);
    const Vector g_body = rotation_.transpose() * gravity;
    for (int node = 0; node < model_->n_nodes(); ++node)
      gravity_force_.template segment<dim>(node * dim) = model_->node_masses()[node] * g_body;
    held_ = impulse_ = u0_ = v0_ = u1_ = v1_ = Eigen::VectorXd::Zero(n);
  }

  // ---- CoupledBody ----------------------------------------------------------------
  std::string kind() const override { return "fe"; }
  mbs::SkinBody<dim>& skin() override { return *this; }

  void advance(double dt) override
  {
    if (!started_)
    {
      model_->start(held_ + gravity_force_);
      started_ = true;
      if (fe_step_ > 0)
        fe_step_to(held_);
    }
    if (fe_step_ == 0)
    {
      const int n = max_step_ > 0 ? std::max(1, int(std::ceil(dt / max_step_ - 1e-9))) : 1;
      for (int k = 0; k < n; ++k)
        model_->step(dt / n, held_ + gravity_force_);
      u1_ = model_->displacement();
      v1_ = model_->velocity();
      time_ += dt;
      return;
    }
    // Sub-cycled: collect the held force's impulse into the FE step's window, and step
    // the FE model whenever the fluid reaches the end of it.
    double remaining = dt;
    while (remaining > 0)
    {
      const double to_end = (window_ + 1) * fe_step_ - time_;
      if (remaining < to_end)
      {
        impulse_ += remaining * held_;
        time_ += remaining;
        break;
      }
      impulse_ += to_end * held_;
      remaining -= to_end;
      ++window_;
      time_ = window_ * fe_step_;
      const Eigen::VectorXd mean = impulse_ / fe_step_;
      impulse_.setZero();
      fe_step_to(mean);
    }
  }

  Vector linear_momentum() const override
  {
    const Eigen::VectorXd v = nodal_velocity();
    Vector p = Vector::Zero();
    for (int node = 0; node < model_->n_nodes(); ++node)
      p += model_->node_masses()[node] * v.template segment<dim>(node * dim);
    return rotation_ * p;
  }
  double mass() const override { return model_->mass(); }
  Vector probe_position() const override
  {
    if (probe_.empty())
      return origin_;
    const Eigen::VectorXd u = nodal_displacement();
    Vector sum = Vector::Zero();
    for (int n : probe_)
      sum += world(n, u);
    return sum / double(probe_.size());
  }
  Matrix frame_rotation() const override { return rotation_; }
  double max_deflection() const override
  {
    const Eigen::VectorXd u = nodal_displacement();
    double largest = 0;
    for (int n : model_->skin_nodes())
      largest = std::max(largest, u.template segment<dim>(n * dim).norm());
    return largest;
  }

  std::vector<double> state() const override
  {
    std::vector<double> s = {double(started_), double(window_), time_};
    for (const auto* v : {&impulse_, &u0_, &v0_, &u1_, &v1_})
      s.insert(s.end(), v->data(), v->data() + v->size());
    const auto model_state = model_->state();
    s.insert(s.end(), model_state.begin(), model_state.end());
    return s;
  }
  void restore(const std::vector<double>& s) override
  {
    const std::size_t n = held_.size();
    if (s.size() < 3 + 5 * n)
      throw std::invalid_argument("fe body: checkpoint state of the wrong size");
    started_ = s[0] != 0;
    window_ = static_cast<long>(s[1]);
    time_ = s[2];
    std::size_t at = 3;
    for (auto* v : {&impulse_, &u0_, &v0_, &u1_, &v1_})
    {
      *v = Eigen::Map<const Eigen::VectorXd>(s.data() + at, n);
      at += n;
    }
    model_->restore(std::vector<double>(s.begin() + at, s.end()));
  }

  // ---- SkinBody -------------------------------------------------------------------
  std::size_t n_skin_nodes() const override { return model_->skin_nodes().size(); }
  const std::vector<std::array<int, dim>>& skin_faces() const override { return faces_; }
  void skin_positions(std::vector<Vector>& x) const override
  {
    const Eigen::VectorXd u = nodal_displacement();
    const auto& nodes = model_->skin_nodes();
    x.resize(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i)
      x[i] = world(nodes[i], u);
  }
  void skin_velocities(std::vector<Vector>& v) const override
  {
    const Eigen::VectorXd velocity = nodal_velocity();
    const auto& nodes = model_->skin_nodes();
    v.resize(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i)
      v[i] = rotation_ * velocity.template segment<dim>(nodes[i] * dim);
  }
  void set_skin_forces(const std::vector<Vector>& f) override
  {
    const auto& nodes = model_->skin_nodes();
    if (f.size() != nodes.size())
      throw std::invalid_argument("fe body: skin forces of the wrong size");
    held_.setZero();
    for (std::size_t i = 0; i < nodes.size(); ++i)
      held_.template segment<dim>(nodes[i] * dim) = rotation_.transpose() * f[i];
  }

private:
  /// The FE step from window_ fe_step_ to the next grid time under the skin force `mean`.
  void fe_step_to(const Eigen::VectorXd& mean)
  {
    u0_ = u1_;
    v0_ = v1_;
    model_->step(fe_step_, mean + gravity_force_);
    u1_ = model_->displacement();
    v1_ = model_->velocity();
  }
  /// Where within the current FE step the fluid is, 0..1 (sub-cycled runs).
  double phase() const { return std::clamp((time_ - window_ * fe_step_) / fe_step_, 0.0, 1.0); }
  /// Cubic Hermite interpolation of the FE states at both ends of the current FE step.
  Eigen::VectorXd nodal_displacement() const
  {
    if (fe_step_ == 0)
      return u1_;
    const double s = phase(), s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * u0_ + (s3 - 2 * s2 + s) * fe_step_ * v0_ +
           (-2 * s3 + 3 * s2) * u1_ + (s3 - s2) * fe_step_ * v1_;
  }
  Eigen::VectorXd nodal_velocity() const
  {
    if (fe_step_ == 0)
      return v1_;
    const double s = phase(), s2 = s * s;
    return (6 * s2 - 6 * s) / fe_step_ * u0_ + (3 * s2 - 4 * s + 1) * v0_ +
           (-6 * s2 + 6 * s) / fe_step_ * u1_ + (3 * s2 - 2 * s) * v1_;
  }
  Vector world(int node, const Eigen::VectorXd& u) const
  {
    return origin_ +
           rotation_ * (model_->node_position(node) + u.template segment<dim>(node * dim));
  }

  std::unique_ptr<fem::FeBodyModel<dim>> model_;
  Matrix rotation_;
  Vector origin_;
  double fe_step_, max_step_;
  std::vector<int> probe_;
  std::vector<std::array<int, dim>> faces_;
  Eigen::VectorXd gravity_force_, held_, impulse_;
  /// FE states at the start (0) and end (1) of the current FE step (node-ordered).
  Eigen::VectorXd u0_, v0_, u1_, v1_;
  bool started_ = false;
  long window_ = 0; ///< FE steps completed beyond the first (sub-cycled runs)
  double time_ = 0; ///< the fluid's time, s
};

class FeKind : public AnyDimensionKind<FeKind>
{
public:
  std::string name() const override { return "fe"; }
  std::string description() const override
  {
    return "fe (the full geometrically nonlinear FE model of a mesh)";
  }

  void declare(BodyKeyDeclarations& keys) const override
  {
    keys.declare("mesh", "", "text",
                 "gmsh .msh (rigid: a closed surface mesh; fe: the body's mesh, as for "
                 "`chipflex reduce`).");
    keys.declare("clamp group", "clamp", "text",
                 "fe, clamped: the boundary group held fixed (as `reduce --clamp`).");
    keys.declare("density", "", "text", "kg/m^3 (required: no default).");
    keys.declare("youngs modulus", "", "text", "E, Pa (required: no default).");
    keys.declare("poisson ratio", "", "text", "nu, -, -1 < nu < 0.5 (required: no default).");
    keys.declare("plane stress", "false", "bool",
                 "fe, 2D: plane stress instead of plane strain (svk only).");
    keys.declare("material model", "svk", "svk|neo-hooke",
                 "fe: St Venant-Kirchhoff or compressible neo-Hooke.");
    keys.declare("degree", "2", "1|2", "fe: element degree.");
    keys.declare("fe time step", "0", "double >= 0",
                 "fe: the FE model's own time step, s, the fluid sub-cycling within it; 0: one "
                 "FE step per fluid step.");
    keys.declare("rayleigh mass", "0", "double >= 0", "Rayleigh alpha, 1/s.");
    keys.declare("rayleigh stiffness", "0", "double >= 0", "Rayleigh beta, s.");
    keys.declare("probe set", "tip", "text",
                 "Node set whose mean is the body's probe point (displacement output).");
  }

  template <int dim>
  static std::unique_ptr<coupling::CoupledBody<dim>> make(const BodyKeys& keys,
                                                          const BodyContext<dim>& context)
  {
    fem::FeBodySettings s;
    s.mesh_file = keys.file("mesh");
    s.material.youngs_modulus = keys.positive("youngs modulus");
    s.material.density = keys.positive("density");
    s.material.poisson_ratio = keys.number("poisson ratio");
    if (!(s.material.poisson_ratio > -1 && s.material.poisson_ratio < 0.5))
      throw InputError(keys.at("poisson ratio"), "must lie in (-1, 0.5)");
    s.material.plane_stress = keys.flag("plane stress");
    if (dim == 3 && s.material.plane_stress)
      throw InputError(keys.at("plane stress"), "is for 2D bodies");
    s.model = fem::parse_hyperelastic_model(keys.text("material model"), keys.at("material model"));
    if (s.material.plane_stress && s.model == fem::HyperelasticModel::neo_hooke)
      throw InputError(keys.at("plane stress"), "exists with material model = svk only");
    s.degree = keys.integer("degree");
    if (context.placement.clamped)
    {
      s.clamp_group = keys.text("clamp group");
      if (s.clamp_group.empty())
        throw InputError(keys.at("clamp group"), "a clamped fe body needs a clamp group");
    }
    if (context.integrator.scheme != mbs::IntegratorOptions::Scheme::generalized_alpha)
      throw InputError(keys.where() + ", implicit",
                       "an fe body is integrated implicitly (generalised-alpha)");
    s.rho_infinity = context.integrator.rho_infinity;
    s.rayleigh_mass = keys.number("rayleigh mass");
    s.rayleigh_stiffness = keys.number("rayleigh stiffness");
    if (context.placement.velocity.norm() > 0 || context.placement.angular_velocity.norm() > 0)
      throw InputError(keys.where() + ", velocity", "an fe body starts at rest");
    const double fe_step = keys.number("fe time step");
    if (fe_step > 0 && context.max_step > 0)
      throw InputError(keys.at("fe time step"), "give either fe time step or max step, not both");

    auto model = std::make_unique<fem::FeBodyModel<dim>>(s);
    const std::string probe_set = keys.text("probe set");
    std::vector<int> probe;
    if (model->has_node_set(probe_set))
      probe = model->node_set(probe_set);
    else if (probe_set != "tip")  // the default may be missing: the frame origin then
      model->node_set(probe_set); // InputError naming the missing group
    return std::make_unique<FeCoupledBody<dim>>(std::move(model), context.placement,
                                                context.gravity, fe_step, context.max_step,
                                                std::move(probe));
  }
};

const BodyKindRegistration registration(std::make_unique<FeKind>());
} // namespace
} // namespace chipflex::apps
