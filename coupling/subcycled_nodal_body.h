#pragma once
// A body stepped on its own time grid by an implicit model of nodal degrees of freedom
// (the `fe` body kind's full nonlinear FE model, fem/fe_body_model.h), coupled to the fluid
// through its skin nodes: the fluid's forces on the skin are nodal forces of the model, the
// skin's positions and velocities are the model's nodes'. Header-only over the model type,
// so coupling/ stays free of deal.II: `Model` provides n_nodes(), node_position(n),
// node_masses(), mass(), skin_nodes(), skin_faces(), start(f), step(dt, f),
// displacement(), velocity(), state() and restore(s) (node-ordered Eigen vectors in the
// model's own coordinates; apps/body_kinds/fe_kind.cc instantiates it with
// fem::FeBodyModel).
//
// Time steps. `fe_step` = 0 takes one model step per fluid step (or `max_step` sub-steps)
// with the skin forces held over it, as the mbs bodies do. A model step costs a few sparse
// factorisations, so with `fe_step` = D > 0 the model steps on its own grid 0, D, 2D, ...
// and the fluid sub-cycles inside each model step: the step T -> T + D is taken when the
// fluid reaches T, under the mean skin force of the fluid's steps in [T - D, T] (the first
// one, before any such window, under the forces of the first fluid step), so the body
// receives the fluid's impulse one model step late. Meanwhile the skin moves on the cubic
// Hermite curve through the model's states (u, v) at T and T + D: positions continuous and
// velocities continuous across model steps, the velocity the curve's derivative.

#include "coupling/coupled_body.h"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace chipflex::coupling
{
template <int dim, class Model>
class SubcycledNodalBody : public CoupledBody<dim>, public mbs::SkinBody<dim>
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  using Matrix = Eigen::Matrix<double, dim, dim>;

  /// `kind` names the body kind in outputs; `rotation` and `origin` place the model's
  /// coordinates in the world (x = origin + rotation (X + u)); `gravity` (world axes) acts
  /// as the consistent nodal load; `probe`: the nodes whose mean is the probe point (none:
  /// the origin).
  SubcycledNodalBody(std::string kind, std::unique_ptr<Model> model, const Matrix& rotation,
                     const Vector& origin, const Vector& gravity, double fe_step, double max_step,
                     std::vector<int> probe)
      : kind_(std::move(kind)), model_(std::move(model)), rotation_(rotation), origin_(origin),
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
  std::string kind() const override { return kind_; }
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
      throw std::invalid_argument(kind_ + " body: checkpoint state of the wrong size");
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
      throw std::invalid_argument(kind_ + " body: skin forces of the wrong size");
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

  std::string kind_;
  std::unique_ptr<Model> model_;
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
} // namespace chipflex::coupling
