// libFuzzer target: the `chipflex run` case reader (apps/case_file.cc and its section
// readers) on any text as a case file: deal.II's ParameterHandler parses it, the readers
// check every value. The dictionary (case_file.dict) gives libFuzzer the keys.
#include "apps/case_file.h"
#include "fuzz_input.h"

#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  chipflex::fuzz::TemporaryInput input(data, size, ".prm");
  try
  {
    const auto c = chipflex::apps::read_case_file(input.path());
    (void)c;
  }
  catch (const std::exception&)
  {
  }
  return 0;
}
