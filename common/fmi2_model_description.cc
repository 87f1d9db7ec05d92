#include "common/fmi2_model_description.h"

#include "common/input_error.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <pugixml.hpp>

namespace chipflex
{
namespace
{
/// Locates errors for a person with an editor: "WHERE: line N" of a byte offset.
class Place
{
public:
  Place(const std::string& xml, const std::string& where) : xml_(xml), where_(where) {}

  std::string at(std::ptrdiff_t offset) const
  {
    if (offset < 0)
      return where_;
    const auto end = xml_.begin() + std::min<std::ptrdiff_t>(offset, xml_.size());
    return where_ + ": line " + std::to_string(1 + std::count(xml_.begin(), end, '\n'));
  }
  std::string at(const pugi::xml_node& node) const { return at(node.offset_debug()); }

private:
  const std::string& xml_;
  const std::string& where_;
};

std::string required(const pugi::xml_node& node, const char* attribute, const Place& place)
{
  const pugi::xml_attribute a = node.attribute(attribute);
  if (!a)
    throw InputError(place.at(node),
                     "<" + std::string(node.name()) + "> has no " + attribute + " attribute");
  return a.value();
}

std::string attribute_or(const pugi::xml_node& node, const char* attribute, const char* fallback)
{
  const pugi::xml_attribute a = node.attribute(attribute);
  return a ? a.value() : fallback;
}

/// An xs:boolean attribute ("true", "false", "1", "0"); absent means false.
bool flag(const pugi::xml_node& node, const char* attribute, const Place& place)
{
  const std::string v = attribute_or(node, attribute, "false");
  if (v == "true" || v == "1")
    return true;
  if (v == "false" || v == "0")
    return false;
  throw InputError(place.at(node), std::string(attribute) + "=\"" + v + "\" is not a boolean");
}

/// valueReference: an xs:unsignedInt.
fmi2ValueReference value_reference(const std::string& text, const std::string& name,
                                   const Place& place, const pugi::xml_node& node)
{
  const bool digits = !text.empty() && text.size() <= 10 &&
                      text.find_first_not_of("0123456789") == std::string::npos;
  if (!digits || std::stoull(text) > 0xffffffffull)
    throw InputError(place.at(node), "variable '" + name + "' has valueReference \"" + text +
                                         "\", not an unsigned integer");
  return static_cast<fmi2ValueReference>(std::stoull(text));
}

Fmi2ScalarVariable scalar_variable(const pugi::xml_node& node, const Place& place)
{
  Fmi2ScalarVariable v;
  v.name = required(node, "name", place);
  v.value_reference = value_reference(required(node, "valueReference", place), v.name, place, node);
  v.causality = attribute_or(node, "causality", "local");
  v.variability = attribute_or(node, "variability", "continuous");
  // Exactly one type element; <Annotations> and whatever a tool adds may stand beside it.
  for (const pugi::xml_node& child : node.children())
  {
    static const char* const types[] = {"Real", "Integer", "Boolean", "String", "Enumeration"};
    if (std::none_of(std::begin(types), std::end(types),
                     [&](const char* t) { return std::strcmp(child.name(), t) == 0; }))
      continue;
    if (!v.type.empty())
      throw InputError(place.at(child), "variable '" + v.name + "' has two type elements");
    v.type = child.name();
    if (const pugi::xml_attribute start = child.attribute("start"))
      v.start = start.value();
  }
  if (v.type.empty())
    throw InputError(place.at(node), "variable '" + v.name +
                                         "' has no type element (Real, Integer, Boolean, "
                                         "String or Enumeration)");
  return v;
}
} // namespace

const Fmi2ScalarVariable* Fmi2ModelDescription::find(const std::string& name) const
{
  const auto it = by_name.find(name);
  return it == by_name.end() ? nullptr : &variables[it->second];
}

Fmi2ModelDescription parse_fmi2_model_description(const std::string& xml, const std::string& where)
{
  const Place place(xml, where);
  pugi::xml_document document;
  const pugi::xml_parse_result parsed = document.load_buffer(xml.data(), xml.size());
  if (!parsed)
    throw InputError(place.at(parsed.offset),
                     std::string("malformed XML: ") + parsed.description());
  const pugi::xml_node root = document.document_element();
  if (std::strcmp(root.name(), "fmiModelDescription") != 0)
    throw InputError(place.at(root), "the root element is <" + std::string(root.name()) +
                                         ">, not <fmiModelDescription>");

  Fmi2ModelDescription md;
  md.fmi_version = required(root, "fmiVersion", place);
  md.model_name = required(root, "modelName", place);
  md.guid = required(root, "guid", place);
  if (const pugi::xml_node cs = root.child("CoSimulation"))
  {
    Fmi2CoSimulation c;
    c.model_identifier = required(cs, "modelIdentifier", place);
    c.needs_execution_tool = flag(cs, "needsExecutionTool", place);
    c.can_handle_variable_communication_step_size =
        flag(cs, "canHandleVariableCommunicationStepSize", place);
    c.can_get_and_set_fmu_state = flag(cs, "canGetAndSetFMUstate", place);
    c.can_serialize_fmu_state = flag(cs, "canSerializeFMUstate", place);
    md.co_simulation = c;
  }
  const pugi::xml_node variables = root.child("ModelVariables");
  if (!variables)
    throw InputError(place.at(root), "<fmiModelDescription> has no <ModelVariables>");
  for (const pugi::xml_node& node : variables.children("ScalarVariable"))
  {
    Fmi2ScalarVariable v = scalar_variable(node, place);
    if (!md.by_name.emplace(v.name, md.variables.size()).second)
      throw InputError(place.at(node), "two variables are called '" + v.name + "'");
    md.variables.push_back(std::move(v));
  }
  return md;
}

Fmi2ModelDescription read_fmi2_model_description(const std::string& path, const std::string& where)
{
  const std::string& name = where.empty() ? path : where;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(name, "cannot open the model description");
  const std::string xml(std::istreambuf_iterator<char>(in), {});
  return parse_fmi2_model_description(xml, name);
}
} // namespace chipflex
