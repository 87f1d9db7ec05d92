#include "meshes/gmsh_session.h"

#include "common/input_error.h"
#include "meshes/msh_text_check.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <gmsh.h>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unistd.h>

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
  check_msh_text(path);
  // gmsh keeps its last error message; only a new one belongs to this file.
  std::string before, error;
  gmsh::logger::getLastError(before);
  gmsh::open(path);
  gmsh::logger::getLastError(error);
  if (!error.empty() && error != before)
    throw InputError(path, "not a readable gmsh mesh (" + error + ")");
}

void write_mesh_file(const std::string& path)
{
  // gmsh picks the format from the extension, so the temporary keeps ".msh".
  const std::string temporary = path + ".tmp" + std::to_string(::getpid()) + ".msh";
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::option::setNumber("Mesh.SaveAll", 0);
  try
  {
    gmsh::write(temporary);
  }
  catch (...)
  {
    std::remove(temporary.c_str());
    throw;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw InputError(path, "cannot write: " + reason);
  }
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
