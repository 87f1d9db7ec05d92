#pragma once
// One instance of a chipflex body FMU: the reduced body of resources/body.h5 in an
// mbs::MultibodySystem (the generalised-alpha integrator that `chipflex run` and
// `chipflex simulate` use), with the FMI 2.0 co-simulation state machine around it.
// fmi2_functions.cc turns the C calls into calls of this class and every exception into
// a status code with a logged message; nothing here throws through the C interface.
//
// States (FMI 2.0, section 4.2.4, simplified): instantiated -> initialisation mode ->
// step complete (doStep) -> terminated; reset returns to instantiated. A doStep that
// the integrator cannot take returns fmi2Discard and leaves the instance at the last
// communication point (the state before the step), so an importer may retry smaller.

#include "common/fmi2_interface.h"
#include "fmu/body_variables.h"

#include <memory>
#include <string>
#include <vector>

namespace chipflex::fmu
{
/// The dimension-dependent body and integrator (body_instance.cc).
class Slave
{
public:
  virtual ~Slave() = default;
  /// Sets the held loads from the input values (indexed by value reference).
  virtual void apply_inputs(const std::vector<double>& values) = 0;
  /// Advances by dt in n equal steps; throws SimulationError if the integrator fails.
  virtual void advance(double dt, int n) = 0;
  virtual double output(const Variable& v) const = 0;
  virtual bool finite() const = 0;
  virtual std::vector<double> save() const = 0;
  virtual void restore(const std::vector<double>& state) = 0;
};

class BodyInstance
{
public:
  enum class State
  {
    instantiated,
    initialization,
    step_complete,
    terminated
  };

  /// Reads `resources/body.h5` below the resource URI and checks the GUID; throws
  /// InputError with the reason.
  BodyInstance(const std::string& name, const std::string& guid, const std::string& resources,
               const fmi2CallbackFunctions& callbacks, bool logging);

  // Each returns the status and logs a message for anything but fmi2OK.
  fmi2Status setup_experiment(bool tolerance_defined, double start_time, bool stop_defined,
                              double stop_time);
  fmi2Status enter_initialization();
  fmi2Status exit_initialization();
  fmi2Status terminate();
  fmi2Status reset();
  fmi2Status get(const fmi2ValueReference vr[], std::size_t n, double value[], VariableType type);
  fmi2Status set(const fmi2ValueReference vr[], std::size_t n, const double value[],
                 VariableType type);
  fmi2Status do_step(double t, double h);
  double time() const { return time_; }

  /// The complete state (values, integrator, time) for fmi2Get/SetFMUstate.
  struct Snapshot
  {
    State state;
    double time, start_time, stop_time;
    bool stop_defined;
    std::vector<double> values, slave;
  };
  Snapshot snapshot() const;
  fmi2Status restore(const Snapshot& s);
  static std::vector<char> serialize(const Snapshot& s);
  /// Throws InputError for bytes that are not a serialised state of this FMU.
  Snapshot deserialize(const char* bytes, std::size_t size) const;

  void set_logging(bool on) { logging_ = on; }
  /// Logs through the importer's logger (errors and warnings always, info when enabled).
  void log(fmi2Status status, const std::string& message) const;
  fmi2Status error(const std::string& message) const
  {
    log(fmi2Error, message);
    return fmi2Error;
  }

private:
  void build_slave();
  std::string describe(fmi2ValueReference vr) const;

  std::string name_;
  fmi2CallbackFunctions callbacks_;
  bool logging_ = false;
  std::string body_path_;
  ReducedBodyData body_;
  BodyVariables variables_;
  std::vector<double> values_; ///< parameters, inputs, constants, by value reference
  std::vector<double> start_values_;
  std::unique_ptr<Slave> slave_;
  bool slave_stale_ = true; ///< a parameter changed since the slave was built
  State state_ = State::instantiated;
  double time_ = 0, start_time_ = 0, stop_time_ = 0;
  bool stop_defined_ = false;
};
} // namespace chipflex::fmu
