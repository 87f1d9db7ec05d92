#include "meshes/gmsh_session.h"

#include "common/input_error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <gmsh.h>
#include <mutex>
#include <sstream>
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

namespace
{
/// gmsh sizes its arrays from the counts and tag ranges of a .msh file's section headers
/// before it reads the data, so a damaged header (a count of 1e16) makes it allocate that
/// much and the run dies for want of memory. No integer in a sound ASCII mesh exceeds the
/// number of its entities, which the file's size bounds: an integer above 16 times the
/// size is refused here, before gmsh sees the file. Binary meshes keep their counts in
/// binary and are left to gmsh.
void check_integers_fit(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return; // gmsh says why
  in.seekg(0, std::ios::end);
  const double limit = 16 * double(in.tellg()) + 1024;
  in.seekg(0);
  std::string line;
  bool format_line = false;
  for (long number = 1; std::getline(in, line); ++number)
  {
    if (format_line) // "4.1 0 8": version, file type (1: binary), data size
    {
      std::istringstream f(line);
      double version = 0;
      int type = 0;
      if (f >> version >> type && type != 0)
        return;
      format_line = false;
    }
    if (line.rfind("$MeshFormat", 0) == 0)
      format_line = true;
    // gmsh 4.8 crashes on a physical-name line without its quoted name; every one of the
    // section's lines must be `dim tag "name"`.
    if (line.rfind("$PhysicalNames", 0) == 0)
    {
      long count = -1;
      if (std::getline(in, line))
        std::istringstream(line) >> count;
      ++number;
      for (long k = 0; k < count && std::getline(in, line); ++k)
      {
        ++number;
        std::istringstream f(line);
        int dim = -1;
        long tag = 0;
        std::string rest;
        f >> dim >> tag;
        std::getline(f >> std::ws, rest);
        if (!f || dim < 0 || dim > 3 || rest.size() < 2 || rest.front() != '"' ||
            rest.find('"', 1) == std::string::npos)
          throw InputError(path + ":" + std::to_string(number),
                           "not a physical name (dim tag \"name\"): '" + line + "'");
      }
      continue;
    }
    std::istringstream tokens(line);
    std::string token;
    while (tokens >> token)
    {
      // Not an integer, or below 100000: gmsh's arrays for that many tags take under a
      // megabyte, while a 9-digit tag alone made it allocate gigabytes (found by fuzzing).
      // Integer coordinates are the only other integers and rarely reach this.
      if (token.find_first_not_of("+-0123456789") != std::string::npos || token.size() < 6)
        continue;
      const double value = std::abs(std::strtod(token.c_str(), nullptr));
      if (value > limit)
        throw InputError(path + ":" + std::to_string(number),
                         "the count or tag " + token + " is larger than a file of this size " +
                             "can hold (a damaged mesh file)");
    }
  }
}
} // namespace

void open_mesh_file(const std::string& path)
{
  check_integers_fit(path);
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
