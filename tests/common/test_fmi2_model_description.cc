// common/fmi2_model_description: a model description written as another tool might
// (data/model_description_reordered.xml: attributes in any order and on several lines,
// single quotes, entities, comments and CDATA that look like variables), a malformed
// file (data/model_description_malformed.xml), and each missing required piece refused
// with one line naming the file and the problem.

#include "common/fmi2_model_description.h"
#include "common/input_error.h"

#include <catch2/catch.hpp>
#include <string>

using namespace chipflex;

namespace
{
const std::string data = CHIPFLEX_TEST_DATA;

/// A minimal valid description with `root_attributes` on the root and `body` inside it.
std::string description(const std::string& root_attributes, const std::string& body)
{
  return "<?xml version=\"1.0\"?>\n<fmiModelDescription " + root_attributes + ">\n" + body +
         "\n</fmiModelDescription>\n";
}

const std::string identity = "fmiVersion=\"2.0\" modelName=\"m\" guid=\"{1}\"";
const std::string one_variable = "<ModelVariables><ScalarVariable name=\"x\" valueReference=\"0\">"
                                 "<Real/></ScalarVariable></ModelVariables>";

std::string error_of(const std::string& xml)
{
  try
  {
    parse_fmi2_model_description(xml, "test.xml");
  }
  catch (const InputError& e)
  {
    return e.what();
  }
  return "no error";
}
} // namespace

TEST_CASE("model description: any attribute order, comments, CDATA, entities", "[common][fmi2]")
{
  const Fmi2ModelDescription md =
      read_fmi2_model_description(data + "/model_description_reordered.xml");
  CHECK(md.fmi_version == "2.0");
  CHECK(md.model_name == "gate & plate");
  CHECK(md.guid == "{8c4e810f-3df3-4a00-8276-176fa3c9f000}");
  REQUIRE(md.co_simulation);
  CHECK(md.co_simulation->model_identifier == "other_tool_body");
  CHECK(md.co_simulation->can_serialize_fmu_state);
  CHECK(md.co_simulation->can_get_and_set_fmu_state);
  CHECK(md.co_simulation->can_handle_variable_communication_step_size);
  CHECK_FALSE(md.co_simulation->needs_execution_tool);

  // Three variables in file order; the commented-out and CDATA ones are not variables.
  REQUIRE(md.variables.size() == 3);
  CHECK(md.find("ghost") == nullptr);
  CHECK(md.find("cdata") == nullptr);
  const Fmi2ScalarVariable* force = md.find("skin.force[0].x");
  REQUIRE(force == &md.variables[0]);
  CHECK(force->value_reference == 7);
  CHECK(force->type == "Real");
  CHECK(force->causality == "input");
  CHECK(force->start == "0");
  const Fmi2ScalarVariable* clamped = md.find("clamped");
  REQUIRE(clamped);
  CHECK(clamped->value_reference == 3);
  CHECK(clamped->type == "Boolean");
  CHECK(clamped->causality == "parameter");
  CHECK(clamped->variability == "fixed");
  CHECK(clamped->start == "true");
  // Defaults of the schema where the attributes are absent; the type beside <Annotations>.
  const Fmi2ScalarVariable* entity = md.find("a < b");
  REQUIRE(entity);
  CHECK(entity->value_reference == 12);
  CHECK(entity->type == "Integer");
  CHECK(entity->causality == "local");
  CHECK(entity->variability == "continuous");
  CHECK(entity->start == "-4");

  // A description without <CoSimulation> (model exchange only) reads, and says so.
  const auto exchange = parse_fmi2_model_description(description(identity, one_variable), "m");
  CHECK_FALSE(exchange.co_simulation);
  REQUIRE(exchange.variables.size() == 1);
  CHECK_FALSE(exchange.variables[0].start);
}

TEST_CASE("model description: malformed XML and missing pieces, one line each", "[common][fmi2]")
{
  const std::string malformed = data + "/model_description_malformed.xml";
  CHECK_THROWS_WITH(read_fmi2_model_description(malformed),
                    Catch::StartsWith(malformed + ": line ") && Catch::Contains("malformed XML"));
  CHECK_THROWS_WITH(read_fmi2_model_description(malformed, "gate.fmu: modelDescription.xml"),
                    Catch::StartsWith("gate.fmu: modelDescription.xml: line "));
  CHECK_THROWS_WITH(read_fmi2_model_description(data + "/no_such_file.xml"),
                    Catch::Contains("no_such_file.xml: cannot open"));

  CHECK(error_of("") == "test.xml: line 1: malformed XML: No document element found");
  CHECK(error_of("<fmiModelDescription") != "no error");
  CHECK(error_of("<other/>") == "test.xml: line 1: the root element is <other>, not "
                                "<fmiModelDescription>");
  CHECK(error_of(description("fmiVersion=\"2.0\" modelName=\"m\"", one_variable)) ==
        "test.xml: line 2: <fmiModelDescription> has no guid attribute");
  CHECK(error_of(description(identity, "")) ==
        "test.xml: line 2: <fmiModelDescription> has no <ModelVariables>");
  CHECK(error_of(description(identity,
                             "<CoSimulation canSerializeFMUstate=\"true\"/>" + one_variable)) ==
        "test.xml: line 3: <CoSimulation> has no modelIdentifier attribute");
  CHECK(error_of(description(identity, "<CoSimulation modelIdentifier=\"m\" "
                                       "canSerializeFMUstate=\"yes\"/>" +
                                           one_variable)) ==
        "test.xml: line 3: canSerializeFMUstate=\"yes\" is not a boolean");
  CHECK(error_of(description(identity, "<ModelVariables>\n<ScalarVariable name=\"x\">"
                                       "<Real/></ScalarVariable></ModelVariables>")) ==
        "test.xml: line 4: <ScalarVariable> has no valueReference attribute");
  CHECK(error_of(description(identity, "<ModelVariables><ScalarVariable name=\"x\" "
                                       "valueReference=\"-1\"><Real/></ScalarVariable>"
                                       "</ModelVariables>")) ==
        "test.xml: line 3: variable 'x' has valueReference \"-1\", not an unsigned integer");
  CHECK(error_of(description(identity, "<ModelVariables><ScalarVariable name=\"x\" "
                                       "valueReference=\"1\"/></ModelVariables>")) ==
        "test.xml: line 3: variable 'x' has no type element (Real, Integer, Boolean, String "
        "or Enumeration)");
  CHECK(error_of(description(identity, "<ModelVariables><ScalarVariable name=\"x\" "
                                       "valueReference=\"1\"><Real/><Integer/></ScalarVariable>"
                                       "</ModelVariables>")) ==
        "test.xml: line 3: variable 'x' has two type elements");
  CHECK(error_of(description(identity, "<ModelVariables>"
                                       "<ScalarVariable name=\"x\" valueReference=\"1\"><Real/>"
                                       "</ScalarVariable>\n"
                                       "<ScalarVariable name=\"x\" valueReference=\"2\"><Real/>"
                                       "</ScalarVariable></ModelVariables>")) ==
        "test.xml: line 4: two variables are called 'x'");
}
