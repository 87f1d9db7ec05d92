// libFuzzer target: the surface reader (meshes/surface_mesh.cc, STL, ASCII and binary)
// on any bytes, read as a 3D wall surface.
#include "fuzz_input.h"
#include "meshes/surface_mesh.h"

#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  chipflex::fuzz::TemporaryInput input(data, size, ".stl");
  try
  {
    const auto surface = chipflex::meshes::read_surface_mesh<3>(input.path());
    (void)surface;
  }
  catch (const std::exception&)
  {
  }
  return 0;
}
