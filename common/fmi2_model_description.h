#pragma once
// What an importer needs of an FMI 2.0 model description (modelDescription.xml, section
// 2.2 of the standard): the identity (fmiVersion, modelName, guid), the co-simulation
// capabilities and the scalar variables. One reader for every importer in chipflex (the
// `fmu` body kind and the tests' FMI master), so that none of them has its own idea of
// XML. The XML itself is read by pugixml: attribute order, comments, CDATA sections,
// entities and line breaks inside tags are the parser's business, not ours.

#include "common/fmi2_interface.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace chipflex
{
/// One <ScalarVariable> (section 2.2.7), with the defaults the schema gives.
struct Fmi2ScalarVariable
{
  std::string name;
  fmi2ValueReference value_reference = 0;
  std::string type;                       ///< Real, Integer, Boolean, String or Enumeration
  std::string causality = "local";        ///< parameter, input, output, local, ...
  std::string variability = "continuous"; ///< constant, fixed, tunable, discrete, continuous
  std::optional<std::string> start;       ///< the start attribute's text, if given
};

/// The <CoSimulation> element (section 4.3.1); capability flags default to false.
struct Fmi2CoSimulation
{
  std::string model_identifier; ///< the library's name: binaries/<platform>/<id>.so
  bool needs_execution_tool = false;
  bool can_handle_variable_communication_step_size = false;
  bool can_get_and_set_fmu_state = false;
  bool can_serialize_fmu_state = false;
};

struct Fmi2ModelDescription
{
  std::string fmi_version, model_name, guid;
  std::optional<Fmi2CoSimulation> co_simulation; ///< absent for a model-exchange-only FMU
  /// In file order: variable k is index k + 1 of <ModelStructure>.
  std::vector<Fmi2ScalarVariable> variables;

  /// The variable called `name`, or nullptr.
  const Fmi2ScalarVariable* find(const std::string& name) const;

  /// name -> position in `variables` (names are unique; the reader checks).
  std::map<std::string, std::size_t> by_name;
};

/// Parses the XML text; `where` names it in errors. Throws InputError (one line, "WHERE:
/// line N: problem" for malformed XML) for XML that is not well formed, a root that is not
/// <fmiModelDescription>, a missing required attribute (fmiVersion, modelName, guid;
/// modelIdentifier of <CoSimulation>; name and valueReference of a variable), a
/// valueReference that is not an unsigned integer, a variable without exactly one type
/// element, or two variables of one name.
Fmi2ModelDescription parse_fmi2_model_description(const std::string& xml, const std::string& where);

/// Reads the file `path` and parses it; errors name `where` (default: the path).
Fmi2ModelDescription read_fmi2_model_description(const std::string& path,
                                                 const std::string& where = "");
} // namespace chipflex
