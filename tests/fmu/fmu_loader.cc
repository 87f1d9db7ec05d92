#include "fmu_loader.h"

#include "common/zip_archive.h"

#include <cstdarg>
#include <cstdio>
#include <dlfcn.h>
#include <stdexcept>

namespace chipflex::test
{
namespace
{
void logger(fmi2ComponentEnvironment, fmi2String, fmi2Status status, fmi2String, fmi2String format,
            ...)
{
  char text[4096];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof text, format, args);
  va_end(args);
  logged().push_back({status, text});
}
} // namespace

std::vector<LogLine>& logged()
{
  static std::vector<LogLine> lines;
  return lines;
}

const fmi2CallbackFunctions& test_callbacks()
{
  static const fmi2CallbackFunctions callbacks{logger, nullptr, nullptr, nullptr, nullptr};
  return callbacks;
}

LoadedFmu::LoadedFmu(const std::string& fmu, const std::string& folder) : folder_(folder)
{
  extract_zip(fmu, folder);
  md_ = read_fmi2_model_description(folder + "/modelDescription.xml");
  if (!md_.co_simulation)
    throw std::runtime_error(fmu + ": not a co-simulation FMU");

  const std::string so = folder + "/binaries/linux64/" + model_identifier() + ".so";
  library_ = dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!library_)
    throw std::runtime_error("dlopen " + so + ": " + dlerror());
  const auto bind = [&](auto& f, const char* name)
  {
    f = reinterpret_cast<std::remove_reference_t<decltype(f)>>(dlsym(library_, name));
    if (!f)
      throw std::runtime_error(so + " does not export " + name);
  };
  bind(fmi_.GetVersion, "fmi2GetVersion");
  bind(fmi_.GetTypesPlatform, "fmi2GetTypesPlatform");
  bind(fmi_.Instantiate, "fmi2Instantiate");
  bind(fmi_.FreeInstance, "fmi2FreeInstance");
  bind(fmi_.SetupExperiment, "fmi2SetupExperiment");
  bind(fmi_.EnterInitializationMode, "fmi2EnterInitializationMode");
  bind(fmi_.ExitInitializationMode, "fmi2ExitInitializationMode");
  bind(fmi_.Terminate, "fmi2Terminate");
  bind(fmi_.Reset, "fmi2Reset");
  bind(fmi_.GetReal, "fmi2GetReal");
  bind(fmi_.SetReal, "fmi2SetReal");
  bind(fmi_.GetInteger, "fmi2GetInteger");
  bind(fmi_.SetInteger, "fmi2SetInteger");
  bind(fmi_.GetBoolean, "fmi2GetBoolean");
  bind(fmi_.SetBoolean, "fmi2SetBoolean");
  bind(fmi_.GetFMUstate, "fmi2GetFMUstate");
  bind(fmi_.SetFMUstate, "fmi2SetFMUstate");
  bind(fmi_.FreeFMUstate, "fmi2FreeFMUstate");
  bind(fmi_.SerializedFMUstateSize, "fmi2SerializedFMUstateSize");
  bind(fmi_.SerializeFMUstate, "fmi2SerializeFMUstate");
  bind(fmi_.DeSerializeFMUstate, "fmi2DeSerializeFMUstate");
  bind(fmi_.DoStep, "fmi2DoStep");
  bind(fmi_.GetRealStatus, "fmi2GetRealStatus");
}

LoadedFmu::~LoadedFmu()
{
  if (library_)
    dlclose(library_);
}

fmi2ValueReference LoadedFmu::vr(const std::string& name) const
{
  if (const Fmi2ScalarVariable* v = md_.find(name))
    return v->value_reference;
  throw std::runtime_error("the FMU has no variable '" + name + "'");
}
} // namespace chipflex::test
