#include "fmu/body_instance.h"

#include "common/input_error.h"
#include "mbs/multibody_system.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

namespace chipflex::fmu
{
namespace
{
/// A file URI (RFC 8089: file:///path, file:/path, file://localhost/path) to a path,
/// with %XX escapes decoded.
std::string path_from_uri(const std::string& uri)
{
  std::string path;
  if (uri.rfind("file://localhost/", 0) == 0)
    path = uri.substr(16);
  else if (uri.rfind("file:///", 0) == 0)
    path = uri.substr(7);
  else if (uri.rfind("file:/", 0) == 0)
    path = uri.substr(5);
  else
    throw InputError("fmuResourceLocation '" + uri + "'", "not a file:// URI");
  std::string decoded;
  for (std::size_t i = 0; i < path.size(); ++i)
    if (path[i] == '%' && i + 2 < path.size())
    {
      decoded.push_back(static_cast<char>(std::stoi(path.substr(i + 1, 2), nullptr, 16)));
      i += 2;
    }
    else
      decoded.push_back(path[i]);
  return decoded;
}

std::string file_bytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path, "cannot open the FMU's body file");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

template <int dim>
class BodySlave : public Slave
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  using Omega = typename mbs::FloatingFrameBody<dim>::Omega;

  BodySlave(const ReducedBodyData& data, const BodyVariables& vars,
            const std::vector<double>& values)
      : vars_(vars)
  {
    const auto value = [&](Role role, int component = 0)
    { return values[vars.first(role) + component]; };
    mbs::FloatingFrameOptions fo;
    const int damping = static_cast<int>(value(Role::damping));
    fo.damping = damping == 1   ? mbs::DampingKind::rayleigh
                 : damping == 2 ? mbs::DampingKind::modal
                                : mbs::DampingKind::none;
    fo.rayleigh_mass = value(Role::rayleigh_alpha);
    fo.rayleigh_stiffness = value(Role::rayleigh_beta);
    fo.modal_damping_ratio = value(Role::modal_damping_ratio);
    mbs::IntegratorOptions io;
    io.rho_infinity = value(Role::rho_infinity);
    system_.set_options(io);
    auto owned = std::make_unique<mbs::FloatingFrameBody<dim>>(data, fo);
    body_ = owned.get();
    system_.add_body(std::move(owned));
    Vector position, gravity;
    for (int d = 0; d < dim; ++d)
    {
      position(d) = value(Role::initial_position, d);
      gravity(d) = value(Role::gravity, d);
    }
    if constexpr (dim == 2)
      body_->set_pose(position, value(Role::initial_rotation));
    else
    {
      const Eigen::Vector3d r(value(Role::initial_rotation, 0), value(Role::initial_rotation, 1),
                              value(Role::initial_rotation, 2));
      const Eigen::Matrix3d a = r.norm() > 0
                                    ? Eigen::AngleAxisd(r.norm(), r / r.norm()).toRotationMatrix()
                                    : Eigen::Matrix3d::Identity();
      body_->set_pose(position, a);
    }
    if (value(Role::clamped) != 0)
      body_->clamp_to_ground();
    system_.set_gravity(gravity);

    // The nodes that carry loads: every node of the sets, and the skin (ascending, so a
    // set's own nodes keep their order and the load sums are those of a set alone).
    std::vector<bool> loaded(data.n_nodes(), false);
    for (const auto& name : vars.set_names())
      for (int node : data.node_sets.at(name))
        loaded[node] = true;
    for (int node : data.skin_nodes)
      loaded[node] = true;
    std::vector<int> slot(data.n_nodes(), -1);
    for (int node = 0; node < data.n_nodes(); ++node)
      if (loaded[node])
      {
        slot[node] = static_cast<int>(load_nodes_.size());
        load_nodes_.push_back(node);
      }
    for (const auto& name : vars.set_names())
    {
      set_nodes_.push_back(data.node_sets.at(name));
      set_slots_.emplace_back();
      for (int node : data.node_sets.at(name))
        set_slots_.back().push_back(slot[node]);
    }
    for (int node : data.skin_nodes)
      skin_slots_.push_back(slot[node]);
    load_forces_.assign(load_nodes_.size(), Vector::Zero());
  }

  void apply_inputs(const std::vector<double>& values) override
  {
    Vector force = Vector::Zero();
    Omega moment = Omega::Zero();
    const int f0 = vars_.first(Role::frame_force), m0 = vars_.first(Role::frame_moment);
    for (int d = 0; d < dim; ++d)
      force(d) = values[f0 + d];
    for (int d = 0; d < Omega::RowsAtCompileTime; ++d)
      moment(d) = values[m0 + d];
    body_->set_frame_load(force, moment);

    for (auto& f : load_forces_)
      f.setZero();
    const int s0 = vars_.first(Role::set_force);
    for (std::size_t s = 0; s < set_slots_.size(); ++s)
    {
      Vector total;
      for (int d = 0; d < dim; ++d)
        total(d) = values[s0 + dim * s + d];
      const Vector share = total / double(set_slots_[s].size());
      for (int slot : set_slots_[s])
        load_forces_[slot] += share;
    }
    const int k0 = vars_.first(Role::skin_force);
    for (std::size_t i = 0; i < skin_slots_.size(); ++i)
      for (int d = 0; d < dim; ++d)
        load_forces_[skin_slots_[i]](d) += values[k0 + dim * i + d];
    body_->set_node_forces(load_nodes_, load_forces_);
  }

  void advance(double dt, int n) override
  {
    for (int k = 0; k < n; ++k)
      system_.step(dt);
  }

  double output(const Variable& v) const override
  {
    const auto& b = *body_;
    switch (v.role)
    {
    case Role::frame_position:
      return b.position()(v.component);
    case Role::frame_orientation:
      if constexpr (dim == 2)
        return b.angle();
      else
      {
        const Eigen::Quaterniond q(b.rotation());
        return v.component == 0 ? q.w() : q.vec()(v.component - 1);
      }
    case Role::frame_velocity:
      return b.frame_velocity()(v.component);
    case Role::frame_angular_velocity:
      return b.angular_velocity()(v.component);
    case Role::modal_coordinate:
      return b.modal_coordinates()(v.index);
    case Role::modal_velocity:
      return b.modal_velocities()(v.index);
    case Role::skin_position:
      return b.node_position(b.skin_node_ids()[v.index])(v.component);
    case Role::skin_velocity:
      return b.node_velocity(b.skin_node_ids()[v.index])(v.component);
    case Role::set_position:
    {
      double sum = 0;
      for (int node : set_nodes_[v.index])
        sum += b.node_position(node)(v.component);
      return sum / double(set_nodes_[v.index].size());
    }
    case Role::linear_momentum:
      return b.linear_momentum()(v.component);
    case Role::kinetic_energy:
      return b.kinetic_energy();
    case Role::strain_energy:
      return b.strain_energy();
    default:
      throw InputError(v.name, "not an output");
    }
  }

  bool finite() const override
  {
    return body_->position().allFinite() && body_->modal_coordinates().allFinite() &&
           body_->velocities().allFinite();
  }

  std::vector<double> save() const override { return system_.save_state(); }
  void restore(const std::vector<double>& state) override { system_.restore_state(state); }

private:
  const BodyVariables& vars_;
  mbs::MultibodySystem<dim> system_;
  mbs::FloatingFrameBody<dim>* body_ = nullptr;
  std::vector<int> load_nodes_;
  std::vector<std::vector<int>> set_nodes_, set_slots_;
  std::vector<int> skin_slots_;
  std::vector<Vector> load_forces_;
};

const char* type_name(VariableType t)
{
  return t == VariableType::real ? "Real" : t == VariableType::integer ? "Integer" : "Boolean";
}
} // namespace

BodyInstance::BodyInstance(const std::string& name, const std::string& guid,
                           const std::string& resources, const fmi2CallbackFunctions& callbacks,
                           bool logging)
    : name_(name), callbacks_(callbacks), logging_(logging),
      body_path_(path_from_uri(resources) + "/body.h5"), body_(read_reduced_body(body_path_)),
      variables_(body_)
{
  const std::string expected = body_guid(file_bytes(body_path_));
  if (guid != expected)
    throw InputError(body_path_, "GUID " + guid + " given, the body file's is " + expected +
                                     " (the FMU's resources do not belong to it)");
  for (const auto& v : variables_.variables())
    values_.push_back(v.start);
  start_values_ = values_;
}

void BodyInstance::log(fmi2Status status, const std::string& message) const
{
  if (!callbacks_.logger || (status == fmi2OK && !logging_))
    return;
  const char* category = status == fmi2OK        ? "logInfo"
                         : status == fmi2Warning ? "logWarning"
                                                 : "logError";
  // The message goes through "%s": the logger is printf-like and the text may hold '%'.
  callbacks_.logger(callbacks_.componentEnvironment, name_.c_str(), status, category, "%s",
                    message.c_str());
}

std::string BodyInstance::describe(fmi2ValueReference vr) const
{
  return vr < variables_.size()
             ? "'" + variables_[vr].name + "' (value reference " + std::to_string(vr) + ")"
             : "value reference " + std::to_string(vr);
}

void BodyInstance::build_slave()
{
  if (slave_ && !slave_stale_)
    return;
  if (body_.dim == 2)
    slave_ = std::make_unique<BodySlave<2>>(body_, variables_, values_);
  else
    slave_ = std::make_unique<BodySlave<3>>(body_, variables_, values_);
  slave_stale_ = false;
}

fmi2Status BodyInstance::setup_experiment(bool, double start_time, bool stop_defined,
                                          double stop_time)
{
  if (state_ != State::instantiated)
    return error("fmi2SetupExperiment: only allowed after fmi2Instantiate or fmi2Reset");
  if (!std::isfinite(start_time) || (stop_defined && !(stop_time >= start_time)))
    return error("fmi2SetupExperiment: start time " + std::to_string(start_time) + ", stop time " +
                 std::to_string(stop_time) + ": not a time interval");
  start_time_ = time_ = start_time;
  stop_defined_ = stop_defined;
  stop_time_ = stop_time;
  return fmi2OK;
}

fmi2Status BodyInstance::enter_initialization()
{
  if (state_ != State::instantiated)
    return error("fmi2EnterInitializationMode: only allowed after fmi2Instantiate or "
                 "fmi2SetupExperiment");
  state_ = State::initialization;
  return fmi2OK;
}

fmi2Status BodyInstance::exit_initialization()
{
  if (state_ != State::initialization)
    return error("fmi2ExitInitializationMode: not in initialisation mode");
  const double h = values_[variables_.first(Role::step_size)];
  const double rho = values_[variables_.first(Role::rho_infinity)];
  const double damping = values_[variables_.first(Role::damping)];
  if (!(h > 0) || !std::isfinite(h))
    return error("parameter 'step_size' = " + std::to_string(h) + ": must be positive");
  if (!(rho >= 0 && rho <= 1))
    return error("parameter 'rho_infinity' = " + std::to_string(rho) + ": must be in [0, 1]");
  if (damping < 0 || damping > 2)
    return error("parameter 'damping' = " + std::to_string(int(damping)) +
                 ": must be 0 (none), 1 (Rayleigh) or 2 (modal)");
  build_slave();
  slave_->apply_inputs(values_);
  state_ = State::step_complete;
  return fmi2OK;
}

fmi2Status BodyInstance::terminate()
{
  if (state_ != State::step_complete)
    return error("fmi2Terminate: only allowed after initialisation");
  state_ = State::terminated;
  return fmi2OK;
}

fmi2Status BodyInstance::reset()
{
  values_ = start_values_;
  slave_.reset();
  slave_stale_ = true;
  state_ = State::instantiated;
  time_ = start_time_ = stop_time_ = 0;
  stop_defined_ = false;
  return fmi2OK;
}

fmi2Status BodyInstance::get(const fmi2ValueReference vr[], std::size_t n, double value[],
                             VariableType type)
{
  if (n > 0 && (!vr || !value))
    return error("fmi2Get" + std::string(type_name(type)) + ": null array");
  for (std::size_t k = 0; k < n; ++k)
  {
    if (vr[k] >= variables_.size() || variables_[vr[k]].type != type)
      return error("fmi2Get" + std::string(type_name(type)) + ": " + describe(vr[k]) +
                   " is not a " + type_name(type) + " variable of this FMU");
    const Variable& v = variables_[vr[k]];
    if (v.causality != Causality::output || v.constant)
      value[k] = values_[vr[k]];
    else
    {
      if (state_ == State::instantiated)
        return error("fmi2GetReal: output " + describe(vr[k]) +
                     " is not available before fmi2EnterInitializationMode");
      build_slave();
      value[k] = slave_->output(v);
    }
  }
  return fmi2OK;
}

fmi2Status BodyInstance::set(const fmi2ValueReference vr[], std::size_t n, const double value[],
                             VariableType type)
{
  const std::string function = "fmi2Set" + std::string(type_name(type));
  if (n > 0 && (!vr || !value))
    return error(function + ": null array");
  if (state_ == State::terminated)
    return error(function + ": the instance is terminated");
  for (std::size_t k = 0; k < n; ++k)
  {
    if (vr[k] >= variables_.size() || variables_[vr[k]].type != type)
      return error(function + ": " + describe(vr[k]) + " is not a " + type_name(type) +
                   " variable of this FMU");
    const Variable& v = variables_[vr[k]];
    if (v.causality == Causality::output)
      return error(function + ": " + describe(vr[k]) + " is an output");
    if (v.causality == Causality::parameter && state_ == State::step_complete)
      return error(function + ": parameter " + describe(vr[k]) +
                   " is fixed after fmi2ExitInitializationMode");
    if (!std::isfinite(value[k]))
      return error(function + ": " + describe(vr[k]) + " = " + std::to_string(value[k]) +
                   " is not finite");
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    values_[vr[k]] = value[k];
    if (variables_[vr[k]].causality == Causality::parameter)
      slave_stale_ = true;
  }
  return fmi2OK;
}

fmi2Status BodyInstance::do_step(double t, double h)
{
  if (state_ != State::step_complete)
    return error("fmi2DoStep: only allowed after fmi2ExitInitializationMode (and before "
                 "fmi2Terminate)");
  if (!std::isfinite(h) || !(h > 0))
    return error("fmi2DoStep: communication step size " + std::to_string(h) + " must be positive");
  if (!std::isfinite(t) || std::abs(t - time_) > 1e-9 * std::max(1.0, std::abs(time_)))
    return error("fmi2DoStep: current communication point " + std::to_string(t) +
                 " s is not the FMU's time " + std::to_string(time_) +
                 " s (roll back with fmi2SetFMUstate)");
  const double h_max = values_[variables_.first(Role::step_size)];
  // Equal internal steps not above step_size (a step a hair above it is not split).
  const int n = std::max(1, static_cast<int>(std::ceil(h / h_max * (1 - 1e-12))));
  const std::vector<double> before = slave_->save();
  std::string failure;
  try
  {
    slave_->apply_inputs(values_);
    slave_->advance(h / n, n);
    if (!slave_->finite())
      failure = "the body's state is not finite";
  }
  catch (const SimulationError& e)
  {
    failure = e.what();
  }
  if (!failure.empty())
  {
    slave_->restore(before);
    log(fmi2Discard, "fmi2DoStep from t = " + std::to_string(t) + " s over " + std::to_string(h) +
                         " s (" + std::to_string(n) + " steps of " + std::to_string(h / n) +
                         " s): " + failure + "; the state stays at t = " + std::to_string(t) +
                         " s (try a smaller step_size or communication step)");
    return fmi2Discard;
  }
  time_ = t + h;
  return fmi2OK;
}

BodyInstance::Snapshot BodyInstance::snapshot() const
{
  return {state_,
          time_,
          start_time_,
          stop_time_,
          stop_defined_,
          values_,
          slave_ ? slave_->save() : std::vector<double>{}};
}

fmi2Status BodyInstance::restore(const Snapshot& s)
{
  values_ = s.values;
  state_ = s.state;
  time_ = s.time;
  start_time_ = s.start_time;
  stop_time_ = s.stop_time;
  stop_defined_ = s.stop_defined;
  slave_stale_ = true;
  slave_.reset();
  if (!s.slave.empty())
  {
    build_slave();
    slave_->restore(s.slave);
    slave_->apply_inputs(values_);
  }
  return fmi2OK;
}

// Serialised layout: "CFXS", version 1 (u32), state (u32), stop_defined (u32), time,
// start, stop (f64), n_values (u64), values, n_slave (u64), slave state; host byte order
// (a state is restored by the same FMU binary on the same platform).
std::vector<char> BodyInstance::serialize(const Snapshot& s)
{
  std::vector<char> out;
  const auto put = [&](const void* p, std::size_t n)
  { out.insert(out.end(), static_cast<const char*>(p), static_cast<const char*>(p) + n); };
  const std::uint32_t header[4] = {0x53584643u, 1u, static_cast<std::uint32_t>(s.state),
                                   s.stop_defined ? 1u : 0u};
  put(header, sizeof header);
  const double times[3] = {s.time, s.start_time, s.stop_time};
  put(times, sizeof times);
  for (const auto* v : {&s.values, &s.slave})
  {
    const std::uint64_t n = v->size();
    put(&n, sizeof n);
    put(v->data(), n * sizeof(double));
  }
  return out;
}

BodyInstance::Snapshot BodyInstance::deserialize(const char* bytes, std::size_t size) const
{
  std::size_t at = 0;
  const auto take = [&](void* p, std::size_t n)
  {
    if (at + n > size)
      throw InputError("fmi2DeSerializeFMUstate", "the serialised state is truncated");
    std::memcpy(p, bytes + at, n);
    at += n;
  };
  std::uint32_t header[4];
  take(header, sizeof header);
  if (header[0] != 0x53584643u || header[1] != 1u || header[2] > 3)
    throw InputError("fmi2DeSerializeFMUstate", "not a serialised state of a chipflex body FMU");
  Snapshot s;
  s.state = static_cast<State>(header[2]);
  s.stop_defined = header[3] != 0;
  double times[3];
  take(times, sizeof times);
  s.time = times[0];
  s.start_time = times[1];
  s.stop_time = times[2];
  for (auto* v : {&s.values, &s.slave})
  {
    std::uint64_t n = 0;
    take(&n, sizeof n);
    if (n > (size - at) / sizeof(double))
      throw InputError("fmi2DeSerializeFMUstate", "the serialised state is truncated");
    v->resize(n);
    take(v->data(), n * sizeof(double));
  }
  if (s.values.size() != values_.size() || at != size)
    throw InputError("fmi2DeSerializeFMUstate", "the serialised state belongs to another body");
  return s;
}
} // namespace chipflex::fmu
