#pragma once
// Test importer of FMI 2.0 co-simulation FMUs, written as an importer would: unpack the
// zip, read modelDescription.xml (GUID, modelIdentifier, variable names -> value
// references), dlopen binaries/linux64/<modelIdentifier>.so and look up the fmi2*
// functions by name. Knows nothing of chipflex's FMU code (it uses only the FMI
// declarations and the model-description reader of common/), so it checks the FMU from
// outside.

#include "common/fmi2_interface.h"
#include "common/fmi2_model_description.h"

#include <string>
#include <vector>

namespace chipflex::test
{
struct Fmi2Functions
{
  decltype(&::fmi2GetVersion) GetVersion;
  decltype(&::fmi2GetTypesPlatform) GetTypesPlatform;
  decltype(&::fmi2Instantiate) Instantiate;
  decltype(&::fmi2FreeInstance) FreeInstance;
  decltype(&::fmi2SetupExperiment) SetupExperiment;
  decltype(&::fmi2EnterInitializationMode) EnterInitializationMode;
  decltype(&::fmi2ExitInitializationMode) ExitInitializationMode;
  decltype(&::fmi2Terminate) Terminate;
  decltype(&::fmi2Reset) Reset;
  decltype(&::fmi2GetReal) GetReal;
  decltype(&::fmi2SetReal) SetReal;
  decltype(&::fmi2GetInteger) GetInteger;
  decltype(&::fmi2SetInteger) SetInteger;
  decltype(&::fmi2GetBoolean) GetBoolean;
  decltype(&::fmi2SetBoolean) SetBoolean;
  decltype(&::fmi2GetFMUstate) GetFMUstate;
  decltype(&::fmi2SetFMUstate) SetFMUstate;
  decltype(&::fmi2FreeFMUstate) FreeFMUstate;
  decltype(&::fmi2SerializedFMUstateSize) SerializedFMUstateSize;
  decltype(&::fmi2SerializeFMUstate) SerializeFMUstate;
  decltype(&::fmi2DeSerializeFMUstate) DeSerializeFMUstate;
  decltype(&::fmi2DoStep) DoStep;
  decltype(&::fmi2GetRealStatus) GetRealStatus;
};

class LoadedFmu
{
public:
  /// Unpacks `fmu` into `folder` and loads its library; throws std::runtime_error.
  LoadedFmu(const std::string& fmu, const std::string& folder);
  ~LoadedFmu();
  LoadedFmu(const LoadedFmu&) = delete;
  LoadedFmu& operator=(const LoadedFmu&) = delete;

  const Fmi2Functions& fmi() const { return fmi_; }
  const std::string& guid() const { return md_.guid; }
  const std::string& model_identifier() const { return md_.co_simulation->model_identifier; }
  std::string resource_uri() const { return "file://" + folder_ + "/resources"; }
  const std::string& folder() const { return folder_; }
  /// Value reference of a variable by name; throws for an unknown name.
  fmi2ValueReference vr(const std::string& name) const;
  bool has(const std::string& name) const { return md_.find(name) != nullptr; }
  const Fmi2ModelDescription& model_description() const { return md_; }

private:
  std::string folder_;
  Fmi2ModelDescription md_;
  void* library_ = nullptr;
  Fmi2Functions fmi_{};
};

/// Messages the FMU logged through the test's logger (status, text).
struct LogLine
{
  fmi2Status status;
  std::string message;
};
std::vector<LogLine>& logged();
/// Callbacks whose logger appends to logged().
const fmi2CallbackFunctions& test_callbacks();
} // namespace chipflex::test
