#include "fmu/fmu_export.h"

#include "common/input_error.h"
#include "common/reduced_body_file.h"
#include "common/zip_archive.h"
#include "fmu/body_variables.h"
#include "fmu/model_description.h"

#include <filesystem>
#include <fstream>
#include <iterator>

namespace chipflex::fmu
{
namespace
{
std::string bytes_of(const std::string& path, const std::string& what)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path, "cannot open the " + what);
  return std::string(std::istreambuf_iterator<char>(in), {});
}
} // namespace

FmuExportSummary export_fmu(const std::string& body_path, const std::string& fmu_path,
                            const FmuExportOptions& options)
{
  if (!valid_model_identifier(options.model_identifier))
    throw InputError("--model-identifier " + options.model_identifier,
                     "must be a C identifier (letters, digits, '_', not starting with a digit)");
  if (!(options.default_step > 0) || !(options.default_stop > 0))
    throw InputError("--step", "the default step and stop time must be positive");
  const ReducedBodyData body = read_reduced_body(body_path);
  const std::string body_bytes = bytes_of(body_path, "body file");
  const std::string library = bytes_of(options.runtime_library, "FMU runtime library");

  const BodyVariables variables(body);
  ModelDescriptionInfo info;
  info.model_name = std::filesystem::path(body_path).stem().string();
  info.model_identifier = options.model_identifier;
  info.guid = body_guid(body_bytes);
  info.generation_tool = body.tool_version.empty() ? "chipflex" : body.tool_version;
  info.description = "chipflex reduced floating-frame body (" + std::to_string(body.dim) + "D, " +
                     std::to_string(body.n_modes()) + " modes, " + std::to_string(body.n_nodes()) +
                     " nodes, " + std::to_string(body.skin_nodes.size()) + " skin nodes" +
                     (body.clamp_set.empty() ? ", free-free" : ", clamp set " + body.clamp_set) +
                     (body.dim == 2 ? "; per metre of depth" : "") + ")";
  info.default_step = options.default_step;
  info.default_stop = options.default_stop;

  write_zip(fmu_path, {{"modelDescription.xml", model_description(variables, info)},
                       {"binaries/linux64/" + options.model_identifier + ".so", library},
                       {"resources/body.h5", body_bytes}});

  FmuExportSummary summary;
  summary.guid = info.guid;
  summary.n_variables = variables.size();
  for (const auto& v : variables.variables())
  {
    summary.n_inputs += v.causality == Causality::input;
    summary.n_outputs += v.causality == Causality::output;
    summary.n_parameters += v.causality == Causality::parameter;
  }
  return summary;
}
} // namespace chipflex::fmu
