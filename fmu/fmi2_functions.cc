// The exported C functions of the chipflex body FMU (FMI 2.0 co-simulation, sections
// 2.1 and 4.2 of the standard). Each one checks its instance pointer, forwards to
// BodyInstance and turns every C++ exception into fmi2Error (fmi2Fatal for memory
// exhaustion) with a logged message: nothing unwinds into the importer.

#include "common/input_error.h"
#include "fmu/body_instance.h"

#include <cstring>
#include <exception>
#include <new>
#include <string>

using chipflex::fmu::BodyInstance;
using chipflex::fmu::VariableType;

namespace
{
BodyInstance* instance(fmi2Component c)
{
  return static_cast<BodyInstance*>(c);
}

/// Runs f on the instance; exceptions become a status and a log line.
template <class F>
fmi2Status guarded(fmi2Component c, const char* function, F&& f)
{
  if (!c)
    return fmi2Error;
  try
  {
    return f(*instance(c));
  }
  catch (const std::bad_alloc&)
  {
    instance(c)->log(fmi2Fatal, std::string(function) + ": out of memory");
    return fmi2Fatal;
  }
  catch (const std::exception& e)
  {
    instance(c)->log(fmi2Error, std::string(function) + ": " + e.what());
    return fmi2Error;
  }
  catch (...)
  {
    instance(c)->log(fmi2Error, std::string(function) + ": unknown failure");
    return fmi2Error;
  }
}

template <class T>
fmi2Status get_values(fmi2Component c, const char* function, const fmi2ValueReference vr[],
                      size_t n, T value[], VariableType type)
{
  return guarded(c, function,
                 [&](BodyInstance& b)
                 {
                   std::vector<double> v(n);
                   const fmi2Status s = b.get(vr, n, v.data(), type);
                   if (s == fmi2OK)
                     for (size_t k = 0; k < n; ++k)
                       value[k] = static_cast<T>(v[k]);
                   return s;
                 });
}

template <class T>
fmi2Status set_values(fmi2Component c, const char* function, const fmi2ValueReference vr[],
                      size_t n, const T value[], VariableType type)
{
  return guarded(c, function,
                 [&](BodyInstance& b)
                 {
                   std::vector<double> v(n);
                   for (size_t k = 0; k < n && value; ++k)
                     v[k] = type == VariableType::boolean ? (value[k] ? 1.0 : 0.0)
                                                          : static_cast<double>(value[k]);
                   return b.set(vr, n, value ? v.data() : nullptr, type);
                 });
}

fmi2Status unsupported(fmi2Component c, const char* function, const char* why)
{
  return guarded(c, function,
                 [&](BodyInstance& b) { return b.error(std::string(function) + ": " + why); });
}
} // namespace

extern "C"
{
  const char* fmi2GetTypesPlatform(void)
  {
    return "default";
  }

  const char* fmi2GetVersion(void)
  {
    return "2.0";
  }

  fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t, const fmi2String[])
  {
    return guarded(c, "fmi2SetDebugLogging",
                   [&](BodyInstance& b)
                   {
                     b.set_logging(loggingOn != fmi2False);
                     return fmi2OK;
                   });
  }

  fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                                fmi2String fmuResourceLocation,
                                const fmi2CallbackFunctions* functions, fmi2Boolean,
                                fmi2Boolean loggingOn)
  {
    const std::string name = instanceName ? instanceName : "";
    const auto fail = [&](const std::string& message) -> fmi2Component
    {
      if (functions && functions->logger)
        functions->logger(functions->componentEnvironment, name.c_str(), fmi2Error, "logError",
                          "%s", ("fmi2Instantiate: " + message).c_str());
      return nullptr;
    };
    if (!functions)
      return nullptr;
    if (fmuType != fmi2CoSimulation)
      return fail("this FMU supports co-simulation only (fmuType must be fmi2CoSimulation)");
    if (!fmuGUID || !fmuResourceLocation)
      return fail("no GUID or no resource location given");
    try
    {
      return new BodyInstance(name, fmuGUID, fmuResourceLocation, *functions,
                              loggingOn != fmi2False);
    }
    catch (const std::exception& e)
    {
      return fail(e.what());
    }
    catch (...)
    {
      return fail("unknown failure");
    }
  }

  void fmi2FreeInstance(fmi2Component c)
  {
    delete instance(c);
  }

  fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real,
                                 fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime)
  {
    return guarded(
        c, "fmi2SetupExperiment",
        [&](BodyInstance& b)
        { return b.setup_experiment(toleranceDefined, startTime, stopTimeDefined, stopTime); });
  }

  fmi2Status fmi2EnterInitializationMode(fmi2Component c)
  {
    return guarded(c, "fmi2EnterInitializationMode",
                   [](BodyInstance& b) { return b.enter_initialization(); });
  }

  fmi2Status fmi2ExitInitializationMode(fmi2Component c)
  {
    return guarded(c, "fmi2ExitInitializationMode",
                   [](BodyInstance& b) { return b.exit_initialization(); });
  }

  fmi2Status fmi2Terminate(fmi2Component c)
  {
    return guarded(c, "fmi2Terminate", [](BodyInstance& b) { return b.terminate(); });
  }

  fmi2Status fmi2Reset(fmi2Component c)
  {
    return guarded(c, "fmi2Reset", [](BodyInstance& b) { return b.reset(); });
  }

  fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         fmi2Real value[])
  {
    return get_values(c, "fmi2GetReal", vr, nvr, value, VariableType::real);
  }

  fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                            fmi2Integer value[])
  {
    return get_values(c, "fmi2GetInteger", vr, nvr, value, VariableType::integer);
  }

  fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                            fmi2Boolean value[])
  {
    return get_values(c, "fmi2GetBoolean", vr, nvr, value, VariableType::boolean);
  }

  fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference[], size_t nvr, fmi2String[])
  {
    if (nvr == 0)
      return c ? fmi2OK : fmi2Error;
    return unsupported(c, "fmi2GetString", "this FMU has no String variables");
  }

  fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2Real value[])
  {
    return set_values(c, "fmi2SetReal", vr, nvr, value, VariableType::real);
  }

  fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                            const fmi2Integer value[])
  {
    return set_values(c, "fmi2SetInteger", vr, nvr, value, VariableType::integer);
  }

  fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                            const fmi2Boolean value[])
  {
    return set_values(c, "fmi2SetBoolean", vr, nvr, value, VariableType::boolean);
  }

  fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference[], size_t nvr,
                           const fmi2String[])
  {
    if (nvr == 0)
      return c ? fmi2OK : fmi2Error;
    return unsupported(c, "fmi2SetString", "this FMU has no String variables");
  }

  fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* FMUstate)
  {
    return guarded(c, "fmi2GetFMUstate",
                   [&](BodyInstance& b)
                   {
                     if (!FMUstate)
                       return b.error("fmi2GetFMUstate: null state pointer");
                     // A state given back is overwritten in place (standard, 2.1.8).
                     if (*FMUstate)
                       *static_cast<BodyInstance::Snapshot*>(*FMUstate) = b.snapshot();
                     else
                       *FMUstate = new BodyInstance::Snapshot(b.snapshot());
                     return fmi2OK;
                   });
  }

  fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate)
  {
    return guarded(c, "fmi2SetFMUstate",
                   [&](BodyInstance& b)
                   {
                     if (!FMUstate)
                       return b.error("fmi2SetFMUstate: null state");
                     return b.restore(*static_cast<BodyInstance::Snapshot*>(FMUstate));
                   });
  }

  fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* FMUstate)
  {
    return guarded(c, "fmi2FreeFMUstate",
                   [&](BodyInstance&)
                   {
                     if (FMUstate)
                     {
                       delete static_cast<BodyInstance::Snapshot*>(*FMUstate);
                       *FMUstate = nullptr;
                     }
                     return fmi2OK;
                   });
  }

  fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t* size)
  {
    return guarded(
        c, "fmi2SerializedFMUstateSize",
        [&](BodyInstance& b)
        {
          if (!FMUstate || !size)
            return b.error("fmi2SerializedFMUstateSize: null argument");
          *size = BodyInstance::serialize(*static_cast<BodyInstance::Snapshot*>(FMUstate)).size();
          return fmi2OK;
        });
  }

  fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate,
                                   fmi2Byte serializedState[], size_t size)
  {
    return guarded(c, "fmi2SerializeFMUstate",
                   [&](BodyInstance& b)
                   {
                     if (!FMUstate || !serializedState)
                       return b.error("fmi2SerializeFMUstate: null argument");
                     const auto bytes =
                         BodyInstance::serialize(*static_cast<BodyInstance::Snapshot*>(FMUstate));
                     if (size < bytes.size())
                       return b.error("fmi2SerializeFMUstate: buffer of " + std::to_string(size) +
                                      " bytes, " + std::to_string(bytes.size()) + " needed");
                     std::memcpy(serializedState, bytes.data(), bytes.size());
                     return fmi2OK;
                   });
  }

  fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                     fmi2FMUstate* FMUstate)
  {
    return guarded(c, "fmi2DeSerializeFMUstate",
                   [&](BodyInstance& b)
                   {
                     if (!serializedState || !FMUstate)
                       return b.error("fmi2DeSerializeFMUstate: null argument");
                     auto s = b.deserialize(serializedState, size);
                     if (*FMUstate)
                       *static_cast<BodyInstance::Snapshot*>(*FMUstate) = std::move(s);
                     else
                       *FMUstate = new BodyInstance::Snapshot(std::move(s));
                     return fmi2OK;
                   });
  }

  fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference[], size_t,
                                          const fmi2ValueReference[], size_t, const fmi2Real[],
                                          fmi2Real[])
  {
    return unsupported(c, "fmi2GetDirectionalDerivative",
                       "not provided (providesDirectionalDerivative = false)");
  }

  fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                         const fmi2Integer[], const fmi2Real[])
  {
    return unsupported(c, "fmi2SetRealInputDerivatives",
                       "inputs are held over a step (canInterpolateInputs = false)");
  }

  fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                          const fmi2Integer[], fmi2Real[])
  {
    return unsupported(c, "fmi2GetRealOutputDerivatives",
                       "not provided (maxOutputDerivativeOrder = 0)");
  }

  fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                        fmi2Real communicationStepSize, fmi2Boolean)
  {
    return guarded(c, "fmi2DoStep",
                   [&](BodyInstance& b)
                   { return b.do_step(currentCommunicationPoint, communicationStepSize); });
  }

  fmi2Status fmi2CancelStep(fmi2Component c)
  {
    return unsupported(c, "fmi2CancelStep",
                       "doStep runs synchronously, there is nothing to cancel");
  }

  fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind, fmi2Status*)
  {
    return unsupported(c, "fmi2GetStatus", "doStep runs synchronously (no pending status)");
  }

  fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real* value)
  {
    return guarded(c, "fmi2GetRealStatus",
                   [&](BodyInstance& b)
                   {
                     if (s != fmi2LastSuccessfulTime || !value)
                       return b.error("fmi2GetRealStatus: only fmi2LastSuccessfulTime");
                     *value = b.time();
                     return fmi2OK;
                   });
  }

  fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind, fmi2Integer*)
  {
    return unsupported(c, "fmi2GetIntegerStatus", "no integer status");
  }

  fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean* value)
  {
    return guarded(c, "fmi2GetBooleanStatus",
                   [&](BodyInstance& b)
                   {
                     if (s != fmi2Terminated || !value)
                       return b.error("fmi2GetBooleanStatus: only fmi2Terminated");
                     *value = fmi2False; // the slave never asks to stop
                     return fmi2OK;
                   });
  }

  fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind, fmi2String*)
  {
    return unsupported(c, "fmi2GetStringStatus", "no string status");
  }
}
