#include "fmu/model_description.h"

#include <cctype>
#include <set>
#include <sstream>
#include <string>

namespace chipflex::fmu
{
namespace
{
std::string xml_escape(const std::string& s)
{
  std::string out;
  for (char c : s)
    switch (c)
    {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    default:
      out.push_back(c);
    }
  return out;
}

std::string number(double v)
{
  // The shortest of 15 or 17 significant digits that reads back to the same double.
  for (int digits : {15, 17})
  {
    std::ostringstream s;
    s.precision(digits);
    s << v;
    if (digits == 17 || std::stod(s.str()) == v)
      return s.str();
  }
  return {};
}

/// SI base-unit exponents of the units the variables use (FMI 2.0, 2.2.2).
const char* base_unit(const std::string& unit)
{
  if (unit == "m")
    return "m=\"1\"";
  if (unit == "s")
    return "s=\"1\"";
  if (unit == "1/s")
    return "s=\"-1\"";
  if (unit == "rad")
    return "rad=\"1\"";
  if (unit == "rad/s")
    return "rad=\"1\" s=\"-1\"";
  if (unit == "m/s")
    return "m=\"1\" s=\"-1\"";
  if (unit == "m/s2")
    return "m=\"1\" s=\"-2\"";
  if (unit == "N")
    return "kg=\"1\" m=\"1\" s=\"-2\"";
  if (unit == "N/m")
    return "kg=\"1\" s=\"-2\"";
  if (unit == "N.m" || unit == "J")
    return "kg=\"1\" m=\"2\" s=\"-2\"";
  if (unit == "N.s")
    return "kg=\"1\" m=\"1\" s=\"-1\"";
  if (unit == "N.s/m")
    return "kg=\"1\" s=\"-1\"";
  if (unit == "J/m")
    return "kg=\"1\" m=\"1\" s=\"-2\"";
  return nullptr;
}
} // namespace

bool valid_model_identifier(const std::string& id)
{
  if (id.empty() || std::isdigit(static_cast<unsigned char>(id[0])))
    return false;
  for (char c : id)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
      return false;
  return true;
}

std::string model_description(const BodyVariables& variables, const ModelDescriptionInfo& info)
{
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"" << xml_escape(info.model_name)
    << "\" guid=\"" << info.guid << "\" description=\"" << xml_escape(info.description)
    << "\" generationTool=\"" << xml_escape(info.generation_tool)
    << "\" variableNamingConvention=\"flat\" numberOfEventIndicators=\"0\">\n";
  x << "  <CoSimulation modelIdentifier=\"" << info.model_identifier
    << "\" needsExecutionTool=\"false\" canHandleVariableCommunicationStepSize=\"true\""
       " canInterpolateInputs=\"false\" maxOutputDerivativeOrder=\"0\""
       " canRunAsynchronuously=\"false\" canBeInstantiatedOnlyOncePerProcess=\"false\""
       " canNotUseMemoryManagementFunctions=\"true\" canGetAndSetFMUstate=\"true\""
       " canSerializeFMUstate=\"true\" providesDirectionalDerivative=\"false\"/>\n";

  std::set<std::string> units;
  for (const auto& v : variables.variables())
    if (!v.unit.empty())
      units.insert(v.unit);
  x << "  <UnitDefinitions>\n";
  for (const auto& u : units)
    if (const char* base = base_unit(u))
      x << "    <Unit name=\"" << u << "\"><BaseUnit " << base << "/></Unit>\n";
  x << "  </UnitDefinitions>\n";
  x << "  <LogCategories>\n"
       "    <Category name=\"logError\" description=\"errors (always logged)\"/>\n"
       "    <Category name=\"logWarning\" description=\"warnings and discarded steps\"/>\n"
       "    <Category name=\"logInfo\" description=\"information (with loggingOn)\"/>\n"
       "  </LogCategories>\n";
  x << "  <DefaultExperiment startTime=\"0\" stopTime=\"" << number(info.default_stop)
    << "\" stepSize=\"" << number(info.default_step) << "\"/>\n";

  x << "  <ModelVariables>\n";
  std::vector<int> outputs, initial_unknowns;
  for (std::size_t k = 0; k < variables.size(); ++k)
  {
    const Variable& v = variables[static_cast<unsigned int>(k)];
    const char* causality = v.causality == Causality::parameter ? "parameter"
                            : v.causality == Causality::input   ? "input"
                                                                : "output";
    const char* variability = v.constant                            ? "constant"
                              : v.causality == Causality::parameter ? "fixed"
                              : v.type == VariableType::real        ? "continuous"
                                                                    : "discrete";
    x << "    <!-- " << k + 1 << " -->\n"
      << "    <ScalarVariable name=\"" << xml_escape(v.name) << "\" valueReference=\"" << k
      << "\" description=\"" << xml_escape(v.description) << "\" causality=\"" << causality
      << "\" variability=\"" << variability << "\"";
    if (v.causality == Causality::parameter || v.constant)
      x << " initial=\"exact\"";
    x << ">\n      ";
    const bool has_start = v.causality != Causality::output || v.constant;
    switch (v.type)
    {
    case VariableType::real:
      x << "<Real";
      if (!v.unit.empty() && base_unit(v.unit))
        x << " unit=\"" << v.unit << "\"";
      if (has_start)
        x << " start=\"" << number(v.start) << "\"";
      x << "/>";
      break;
    case VariableType::integer:
      x << "<Integer";
      if (has_start)
        x << " start=\"" << static_cast<long>(v.start) << "\"";
      x << "/>";
      break;
    case VariableType::boolean:
      x << "<Boolean";
      if (has_start)
        x << " start=\"" << (v.start != 0 ? "true" : "false") << "\"";
      x << "/>";
      break;
    }
    x << "\n    </ScalarVariable>\n";
    if (v.causality == Causality::output)
      outputs.push_back(static_cast<int>(k) + 1);
    if (v.causality == Causality::output && !v.constant)
      initial_unknowns.push_back(static_cast<int>(k) + 1);
  }
  x << "  </ModelVariables>\n";

  // Outputs depend on no input directly (the inputs act through the next doStep); at
  // initialisation they follow from the parameters (dependencies left out: all).
  x << "  <ModelStructure>\n    <Outputs>\n";
  for (int index : outputs)
    x << "      <Unknown index=\"" << index << "\" dependencies=\"\"/>\n";
  x << "    </Outputs>\n    <InitialUnknowns>\n";
  for (int index : initial_unknowns)
    x << "      <Unknown index=\"" << index << "\"/>\n";
  x << "    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n";
  return x.str();
}
} // namespace chipflex::fmu
