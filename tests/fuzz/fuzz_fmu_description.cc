// libFuzzer target: the FMU importer's inputs: modelDescription.xml
// (common/fmi2_model_description.cc, pugixml) on any text, and the FMU's zip archive
// (common/zip_archive.cc, libzip) on any bytes.
#include "common/fmi2_model_description.h"
#include "common/zip_archive.h"
#include "fuzz_input.h"

#include <exception>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  try
  {
    const auto d = chipflex::parse_fmi2_model_description(
        std::string(reinterpret_cast<const char*>(data), size), "modelDescription.xml");
    (void)d;
  }
  catch (const std::exception&)
  {
  }
  chipflex::fuzz::TemporaryInput input(data, size, ".fmu");
  try
  {
    const auto entries = chipflex::read_zip(input.path());
    (void)entries;
  }
  catch (const std::exception&)
  {
  }
  return 0;
}
