#include "coupling/fmu_body.h"

#include "common/fmi2_interface.h"
#include "common/fmi2_model_description.h"
#include "common/input_error.h"
#include "common/zip_archive.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <dlfcn.h>
#include <filesystem>
#include <limits>

namespace chipflex::coupling
{
namespace
{
using Vector = Eigen::Vector2d;

void logger(fmi2ComponentEnvironment environment, fmi2String, fmi2Status status, fmi2String,
            fmi2String format, ...)
{
  char text[2048];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof text, format, args);
  va_end(args);
  if (status != fmi2OK && environment)
    *static_cast<std::string*>(environment) = text;
}

class FmuBody : public CoupledBody<2>, public mbs::SkinBody<2>
{
public:
  using Vector = Eigen::Vector2d;

  FmuBody(const FmuBodySettings& d, const Vector& gravity) : fmu_(d.fmu_file), name_(d.name)
  {
    char folder[] = "/tmp/chipflex_fmu_body_XXXXXX";
    if (!mkdtemp(folder))
      throw InputError(fmu_, "cannot create a folder to unpack the FMU");
    folder_ = folder;
    try
    {
      load(d, gravity);
    }
    catch (...)
    {
      release();
      throw;
    }
  }
  ~FmuBody() override { release(); }

  // ---- CoupledBody
  std::string kind() const override { return "fmu"; }
  mbs::SkinBody<2>& skin() override { return *this; }
  void advance(double dt) override
  {
    if (dt <= 0)
      return;
    check(fmi_.SetReal(c_, force_vr_.data(), force_vr_.size(), forces_.data()), "fmi2SetReal");
    check(fmi_.DoStep(c_, time_, dt, fmi2True), "fmi2DoStep");
    time_ += dt;
    refresh();
  }
  Vector linear_momentum() const override { return momentum_; }
  /// Unknown: the FMU variables carry no mass (contact refuses such a body).
  double mass() const override { return std::numeric_limits<double>::quiet_NaN(); }
  Vector probe_position() const override { return probe_; }
  std::vector<double> state() const override
  {
    fmi2FMUstate s = nullptr;
    check(fmi_.GetFMUstate(c_, &s), "fmi2GetFMUstate");
    std::size_t size = 0;
    check(fmi_.SerializedFMUstateSize(c_, s, &size), "fmi2SerializedFMUstateSize");
    std::vector<fmi2Byte> bytes(size);
    check(fmi_.SerializeFMUstate(c_, s, bytes.data(), size), "fmi2SerializeFMUstate");
    fmi_.FreeFMUstate(c_, &s);
    // [time, byte count, bytes packed 8 to a double]
    std::vector<double> out(2 + (size + 7) / 8, 0.0);
    out[0] = time_;
    out[1] = static_cast<double>(size);
    std::memcpy(out.data() + 2, bytes.data(), size);
    return out;
  }
  void restore(const std::vector<double>& state) override
  {
    if (state.size() < 2 || state.size() != 2 + (static_cast<std::size_t>(state[1]) + 7) / 8)
      throw InputError(fmu_, "checkpoint state of the wrong size for an FMU body");
    const std::size_t size = static_cast<std::size_t>(state[1]);
    std::vector<fmi2Byte> bytes(size);
    std::memcpy(bytes.data(), state.data() + 2, size);
    fmi2FMUstate s = nullptr;
    check(fmi_.DeSerializeFMUstate(c_, bytes.data(), size, &s), "fmi2DeSerializeFMUstate");
    check(fmi_.SetFMUstate(c_, s), "fmi2SetFMUstate");
    fmi_.FreeFMUstate(c_, &s);
    time_ = state[0];
    refresh();
  }

  // ---- SkinBody
  std::size_t n_skin_nodes() const override { return positions_.size(); }
  const std::vector<std::array<int, 2>>& skin_faces() const override { return faces_; }
  void skin_positions(std::vector<Vector>& x) const override { x = positions_; }
  void skin_velocities(std::vector<Vector>& v) const override { v = velocities_; }
  void set_skin_forces(const std::vector<Vector>& f) override
  {
    if (f.size() != positions_.size())
      throw std::logic_error("FmuBody::set_skin_forces: wrong number of forces");
    for (std::size_t i = 0; i < f.size(); ++i)
    {
      forces_[2 * i] = f[i].x();
      forces_[2 * i + 1] = f[i].y();
    }
  }

private:
  struct Functions
  {
    decltype(&::fmi2Instantiate) Instantiate;
    decltype(&::fmi2FreeInstance) FreeInstance;
    decltype(&::fmi2SetupExperiment) SetupExperiment;
    decltype(&::fmi2EnterInitializationMode) EnterInitializationMode;
    decltype(&::fmi2ExitInitializationMode) ExitInitializationMode;
    decltype(&::fmi2Terminate) Terminate;
    decltype(&::fmi2GetReal) GetReal;
    decltype(&::fmi2SetReal) SetReal;
    decltype(&::fmi2GetInteger) GetInteger;
    decltype(&::fmi2SetInteger) SetInteger;
    decltype(&::fmi2SetBoolean) SetBoolean;
    decltype(&::fmi2DoStep) DoStep;
    decltype(&::fmi2GetFMUstate) GetFMUstate;
    decltype(&::fmi2SetFMUstate) SetFMUstate;
    decltype(&::fmi2FreeFMUstate) FreeFMUstate;
    decltype(&::fmi2SerializedFMUstateSize) SerializedFMUstateSize;
    decltype(&::fmi2SerializeFMUstate) SerializeFMUstate;
    decltype(&::fmi2DeSerializeFMUstate) DeSerializeFMUstate;
  };

  void check(fmi2Status s, const char* what) const
  {
    if (s == fmi2OK || s == fmi2Warning)
      return;
    const std::string message = "body '" + name_ + "' (" + fmu_ + "): " + what + " returned " +
                                (s == fmi2Discard ? "fmi2Discard" : "an error") +
                                (last_message_.empty() ? "" : ": " + last_message_);
    if (time_ > 0 || s == fmi2Discard)
      throw SimulationError(message + " at t = " + std::to_string(time_) + " s");
    throw InputError(fmu_, message);
  }

  const Fmi2ScalarVariable* find(const std::string& name, const char* type) const
  {
    const Fmi2ScalarVariable* v = md_.find(name);
    return v && v->type == type ? v : nullptr;
  }
  fmi2ValueReference need(const std::string& name, const char* type) const
  {
    if (const auto* v = find(name, type))
      return v->value_reference;
    throw InputError(fmu_, "the FMU has no " + std::string(type) + " variable '" + name +
                               "' (an fmu body needs the skin variables of "
                               "docs/export_fmu_sid.md)");
  }

  void set_real(const std::string& name, double value)
  {
    if (const auto* v = find(name, "Real"))
      check(fmi_.SetReal(c_, &v->value_reference, 1, &value), "fmi2SetReal");
  }

  void load(const FmuBodySettings& d, const Vector& gravity)
  {
    extract_zip(fmu_, folder_);
    const std::string description = folder_ + "/modelDescription.xml";
    if (!std::filesystem::exists(description))
      throw InputError(fmu_, "no modelDescription.xml in the FMU");
    md_ = read_fmi2_model_description(description, fmu_ + ": modelDescription.xml");
    if (md_.fmi_version != "2.0")
      throw InputError(fmu_, "FMI version '" + md_.fmi_version + "', an fmu body needs FMI 2.0");
    if (!md_.co_simulation)
      throw InputError(fmu_, "not a co-simulation FMU (no <CoSimulation>)");
    const std::string so =
        folder_ + "/binaries/linux64/" + md_.co_simulation->model_identifier + ".so";
    library_ = dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library_)
      throw InputError(fmu_, std::string("cannot load its library: ") + dlerror());
    const auto bind = [&](auto& f, const char* name)
    {
      f = reinterpret_cast<std::remove_reference_t<decltype(f)>>(dlsym(library_, name));
      if (!f)
        throw InputError(fmu_, std::string("its library does not export ") + name);
    };
    bind(fmi_.Instantiate, "fmi2Instantiate");
    bind(fmi_.FreeInstance, "fmi2FreeInstance");
    bind(fmi_.SetupExperiment, "fmi2SetupExperiment");
    bind(fmi_.EnterInitializationMode, "fmi2EnterInitializationMode");
    bind(fmi_.ExitInitializationMode, "fmi2ExitInitializationMode");
    bind(fmi_.Terminate, "fmi2Terminate");
    bind(fmi_.GetReal, "fmi2GetReal");
    bind(fmi_.SetReal, "fmi2SetReal");
    bind(fmi_.GetInteger, "fmi2GetInteger");
    bind(fmi_.SetInteger, "fmi2SetInteger");
    bind(fmi_.SetBoolean, "fmi2SetBoolean");
    bind(fmi_.DoStep, "fmi2DoStep");
    bind(fmi_.GetFMUstate, "fmi2GetFMUstate");
    bind(fmi_.SetFMUstate, "fmi2SetFMUstate");
    bind(fmi_.FreeFMUstate, "fmi2FreeFMUstate");
    bind(fmi_.SerializedFMUstateSize, "fmi2SerializedFMUstateSize");
    bind(fmi_.SerializeFMUstate, "fmi2SerializeFMUstate");
    bind(fmi_.DeSerializeFMUstate, "fmi2DeSerializeFMUstate");

    // The skin: nodes counted from the names, faces from the constants.
    const char* axis[] = {"x", "y"};
    const auto skin_name = [&](const char* what, std::size_t i, int c)
    { return "skin." + std::string(what) + "[" + std::to_string(i) + "]." + axis[c]; };
    for (std::size_t i = 0; find(skin_name("position", i, 0), "Real"); ++i)
      for (int c = 0; c < 2; ++c)
      {
        position_vr_.push_back(need(skin_name("position", i, c), "Real"));
        velocity_vr_.push_back(need(skin_name("velocity", i, c), "Real"));
        force_vr_.push_back(need(skin_name("force", i, c), "Real"));
      }
    const std::size_t n = position_vr_.size() / 2;
    if (n < 2)
      throw InputError(fmu_, "the FMU has no skin (variables skin.position[i].x|y)");
    std::vector<fmi2ValueReference> face_vr;
    for (std::size_t f = 0; find("skin.face[" + std::to_string(f) + "][0]", "Integer"); ++f)
      for (int c = 0; c < 2; ++c)
        face_vr.push_back(
            need("skin.face[" + std::to_string(f) + "][" + std::to_string(c) + "]", "Integer"));
    if (face_vr.empty())
      throw InputError(fmu_, "the FMU has no skin faces (Integer skin.face[f][0|1])");
    forces_.assign(2 * n, 0.0);
    positions_.resize(n);
    velocities_.resize(n);

    callbacks_ = {logger, nullptr, nullptr, nullptr, &last_message_};
    c_ = fmi_.Instantiate(d.name.c_str(), fmi2CoSimulation, md_.guid.c_str(),
                          ("file://" + folder_ + "/resources").c_str(), &callbacks_, fmi2False,
                          fmi2False);
    if (!c_)
      throw InputError(fmu_, "fmi2Instantiate failed" +
                                 (last_message_.empty() ? "" : ": " + last_message_));
    check(fmi_.SetupExperiment(c_, fmi2False, 0, 0, fmi2False, 0), "fmi2SetupExperiment");
    if (const auto* v = find("clamped", "Boolean"))
    {
      const fmi2Boolean b = d.clamped ? fmi2True : fmi2False;
      check(fmi_.SetBoolean(c_, &v->value_reference, 1, &b), "fmi2SetBoolean");
    }
    // max step 0 = one body step per fluid step: an internal step no fluid step exceeds.
    set_real("step_size", d.max_step > 0 ? d.max_step : 1e30);
    set_real("rho_infinity", d.rho_infinity);
    if (d.modal_damping > 0 && (d.rayleigh_mass > 0 || d.rayleigh_stiffness > 0))
      throw InputError("body '" + d.name + "', damping",
                       "give either a modal damping ratio or Rayleigh coefficients, not both");
    const int damping = d.modal_damping > 0                                 ? 2
                        : (d.rayleigh_mass > 0 || d.rayleigh_stiffness > 0) ? 1
                                                                            : 0;
    if (const auto* v = find("damping", "Integer"))
      check(fmi_.SetInteger(c_, &v->value_reference, 1, &damping), "fmi2SetInteger");
    else if (damping != 0)
      throw InputError(fmu_, "the FMU has no 'damping' parameter for the case's damping");
    set_real("rayleigh_alpha", d.rayleigh_mass);
    set_real("rayleigh_beta", d.rayleigh_stiffness);
    set_real("modal_damping_ratio", d.modal_damping);
    set_real("gravity.x", gravity.x());
    set_real("gravity.y", gravity.y());
    set_real("initial.position.x", d.position.x());
    set_real("initial.position.y", d.position.y());
    set_real("initial.angle", d.angle);
    check(fmi_.EnterInitializationMode(c_), "fmi2EnterInitializationMode");
    check(fmi_.ExitInitializationMode(c_), "fmi2ExitInitializationMode");

    std::vector<fmi2Integer> corners(face_vr.size());
    check(fmi_.GetInteger(c_, face_vr.data(), face_vr.size(), corners.data()), "fmi2GetInteger");
    for (std::size_t f = 0; f < corners.size() / 2; ++f)
    {
      for (int c = 0; c < 2; ++c)
        if (corners[2 * f + c] < 0 || corners[2 * f + c] >= static_cast<int>(n))
          throw InputError(fmu_, "skin face " + std::to_string(f) + " names skin node " +
                                     std::to_string(corners[2 * f + c]) + " of " +
                                     std::to_string(n));
      faces_.push_back({corners[2 * f], corners[2 * f + 1]});
    }
    const std::string probe = "set." + d.probe_set + ".position.";
    if (find(probe + "x", "Real") && find(probe + "y", "Real"))
      probe_vr_ = {need(probe + "x", "Real"), need(probe + "y", "Real")};
    if (find("linear_momentum.x", "Real") && find("linear_momentum.y", "Real"))
      momentum_vr_ = {need("linear_momentum.x", "Real"), need("linear_momentum.y", "Real")};
    refresh();
  }

  /// Reads the skin, probe and momentum after a step.
  void refresh()
  {
    std::vector<double> x(position_vr_.size()), v(velocity_vr_.size());
    check(fmi_.GetReal(c_, position_vr_.data(), x.size(), x.data()), "fmi2GetReal");
    check(fmi_.GetReal(c_, velocity_vr_.data(), v.size(), v.data()), "fmi2GetReal");
    for (std::size_t i = 0; i < positions_.size(); ++i)
    {
      positions_[i] = Vector(x[2 * i], x[2 * i + 1]);
      velocities_[i] = Vector(v[2 * i], v[2 * i + 1]);
    }
    if (probe_vr_.size() == 2)
      check(fmi_.GetReal(c_, probe_vr_.data(), 2, probe_.data()), "fmi2GetReal");
    else
    {
      probe_.setZero();
      for (const auto& p : positions_)
        probe_ += p / double(positions_.size());
    }
    if (momentum_vr_.size() == 2)
      check(fmi_.GetReal(c_, momentum_vr_.data(), 2, momentum_.data()), "fmi2GetReal");
  }

  void release()
  {
    if (c_)
    {
      fmi_.Terminate(c_);
      fmi_.FreeInstance(c_);
      c_ = nullptr;
    }
    if (library_)
    {
      dlclose(library_);
      library_ = nullptr;
    }
    std::error_code ec;
    std::filesystem::remove_all(folder_, ec);
  }

  std::string fmu_, name_, folder_;
  Fmi2ModelDescription md_;
  void* library_ = nullptr;
  Functions fmi_{};
  fmi2CallbackFunctions callbacks_{};
  mutable std::string last_message_;
  fmi2Component c_ = nullptr;
  double time_ = 0;
  std::vector<fmi2ValueReference> position_vr_, velocity_vr_, force_vr_, probe_vr_, momentum_vr_;
  std::vector<double> forces_;
  std::vector<Vector> positions_, velocities_;
  std::vector<std::array<int, 2>> faces_;
  Vector probe_ = Vector::Zero(), momentum_ = Vector::Zero();
};
} // namespace

std::unique_ptr<CoupledBody<2>> make_fmu_body(const FmuBodySettings& d, const Vector& gravity)
{
  if (d.fmu_file.empty())
    throw InputError("body '" + d.name + "', fmu file", "an fmu body needs an FMU file");
  if (!d.implicit)
    throw InputError("body '" + d.name + "', implicit", "an fmu body integrates itself");
  if (d.velocity.norm() > 0)
    throw InputError("body '" + d.name + "', velocity",
                     "an fmu body starts at rest (the FMU has no initial velocity parameter)");
  return std::make_unique<FmuBody>(d, gravity);
}
} // namespace chipflex::coupling
