#pragma once
// modelDescription.xml of a chipflex body FMU (FMI 2.0, section 2.2: the FMU's
// variables, capabilities and structure; schema fmi2ModelDescription.xsd of the standard).

#include "fmu/body_variables.h"

#include <string>

namespace chipflex::fmu
{
struct ModelDescriptionInfo
{
  std::string model_name;       ///< e.g. the body file's name
  std::string model_identifier; ///< the library's name: binaries/linux64/<id>.so
  std::string guid;             ///< body_guid() of the body file
  std::string description;
  std::string generation_tool; ///< e.g. "chipflex 0.1.0"
  double default_step = 1e-4;  ///< DefaultExperiment stepSize, s
  double default_stop = 0.1;   ///< DefaultExperiment stopTime, s
};

/// The XML text (UTF-8).
std::string model_description(const BodyVariables& variables, const ModelDescriptionInfo& info);

/// True if `id` is a C identifier (what FMI requires of a modelIdentifier).
bool valid_model_identifier(const std::string& id);
} // namespace chipflex::fmu
