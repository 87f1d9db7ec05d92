#include "meshes/gmsh_session.h"

#include "common/input_error.h"

#include <gmsh.h>
#include <mutex>
#include <stdexcept>

namespace chipflex::meshes
{
namespace
{
/// Finalises gmsh when the program ends (static destruction order: after main).
struct GmshLifetime
{
  GmshLifetime()
  {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);
    gmsh::option::setNumber("General.AbortOnError", 0);
  }
  ~GmshLifetime() { gmsh::finalize(); }
};

std::string last_gmsh_error(const std::string& fallback)
{
  std::string error;
  try
  {
    gmsh::logger::getLastError(error);
  }
  catch (...)
  {
  }
  return error.empty() ? fallback : error;
}
} // namespace

void open_mesh_file(const std::string& path)
{
  // gmsh keeps its last error message; only a new one belongs to this file.
  std::string before, error;
  gmsh::logger::getLastError(before);
  gmsh::open(path);
  gmsh::logger::getLastError(error);
  if (!error.empty() && error != before)
    throw InputError(path, "not a readable gmsh mesh (" + error + ")");
}

void ensure_gmsh()
{
  static GmshLifetime lifetime;
}

void with_gmsh_model(const std::string& where, const std::function<void()>& action)
{
  ensure_gmsh();
  try
  {
    gmsh::clear();
    action();
  }
  catch (const InputError&)
  {
    gmsh::clear();
    throw;
  }
  catch (const std::exception& e)
  {
    gmsh::clear();
    throw InputError(where, last_gmsh_error(e.what()));
  }
  catch (...)
  {
    gmsh::clear();
    throw InputError(where, last_gmsh_error("gmsh failed"));
  }
  gmsh::clear();
}
} // namespace chipflex::meshes
