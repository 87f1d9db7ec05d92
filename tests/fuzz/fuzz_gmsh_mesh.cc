// libFuzzer target: the gmsh mesh reader (fem/gmsh_reader.cc) on any bytes as a .msh file.
// gmsh parses the file; the reader then checks dimensions, element types, physical
// groups and node numbering. Anything but a clean result or an exception is a bug.
#include "fem/gmsh_reader.h"
#include "fuzz_input.h"

#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  chipflex::fuzz::TemporaryInput input(data, size, ".msh");
  try
  {
    const auto mesh = chipflex::fem::read_gmsh_mesh(input.path());
    (void)mesh;
  }
  catch (const std::exception&)
  {
  }
  return 0;
}
