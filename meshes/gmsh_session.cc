#include "meshes/gmsh_session.h"

#include "common/input_error.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <gmsh.h>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

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
bool is_integer(const std::string& token)
{
  return !token.empty() && token.find_first_not_of("+-0123456789") == std::string::npos;
}

bool is_number(const std::string& token)
{
  char* end = nullptr;
  std::strtod(token.c_str(), &end);
  return !token.empty() && *end == '\0';
}

std::vector<std::string> tokens_of(const std::string& line)
{
  std::istringstream in(line);
  std::vector<std::string> tokens;
  for (std::string token; in >> token;)
    tokens.push_back(token);
  return tokens;
}

/// One line of an MSH 4.1 `$Entities` section, as gmsh writes it: a point is `tag x y z
/// nPhysicals physicals...`, a curve, surface or volume `tag minX minY minZ maxX maxY maxZ
/// nPhysicals physicals... nBounding bounding...`. gmsh reads these with fscanf and sizes
/// vectors by the counts, so a line whose counts point at a coordinate (a line cut short,
/// another one's tail) makes it read a number out of a float and allocate gigabytes.
bool is_entity_line(const std::vector<std::string>& t, bool point)
{
  const std::size_t n_coordinates = point ? 3 : 6;
  std::size_t at = 1 + n_coordinates;
  if (t.size() <= at || !is_integer(t[0]))
    return false;
  for (std::size_t k = 1; k < at; ++k)
    if (!is_number(t[k]))
      return false;
  for (int counted_list = 0; counted_list < (point ? 1 : 2); ++counted_list)
  {
    if (at >= t.size() || !is_integer(t[at]) || t[at][0] == '-')
      return false;
    const double count = std::strtod(t[at].c_str(), nullptr);
    if (count > double(t.size() - at - 1))
      return false;
    for (std::size_t k = 1; k <= std::size_t(count); ++k)
      if (!is_integer(t[at + k]))
        return false;
    at += 1 + std::size_t(count);
  }
  return at == t.size();
}

/// gmsh sizes its arrays from the counts and tag ranges of a .msh file's section headers
/// before it reads the data, so a damaged header (a count of 1e16) makes it allocate that
/// much and the run dies for want of memory. No integer in a sound ASCII mesh exceeds the
/// number of its entities, which the file's size bounds: an integer above 16 times the
/// size is refused here, before gmsh sees the file. The file must start as a mesh
/// (`$MeshFormat`), the lines of an MSH 4.1 `$Entities` section must hold what their
/// counts say, and `$PhysicalNames` lines their quoted names. Binary meshes keep their
/// counts in binary and are left to gmsh.
void check_mesh_headers(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return; // gmsh says why
  in.seekg(0, std::ios::end);
  const double limit = 16 * double(in.tellg()) + 1024;
  in.seekg(0);
  std::string line;
  long number = 0;
  auto next_line = [&]
  {
    ++number;
    return bool(std::getline(in, line));
  };
  auto refuse = [&](const std::string& what)
  { throw InputError(path + ":" + std::to_string(number), what); };
  auto check_integers = [&]
  {
    for (const auto& token : tokens_of(line))
      // Below 100000, gmsh's arrays for that many tags take under a megabyte, while a
      // 9-digit tag alone made it allocate gigabytes (found by fuzzing). Integer
      // coordinates are the only other integers and rarely reach this.
      if (is_integer(token) && token.size() >= 6 &&
          std::abs(std::strtod(token.c_str(), nullptr)) > limit)
        refuse("the count or tag " + token + " is larger than a file of this size can hold " +
               "(a damaged mesh file)");
  };
  // gmsh reads a file that does not start with a mesh format section as a .geo script: a
  // language with its own parser (which fuzzing crashed with a division by zero) and a
  // `System` command. A mesh file must be a mesh.
  if (!next_line() || line.rfind("$MeshFormat", 0) != 0)
    refuse("not a gmsh mesh: the file does not start with $MeshFormat");
  in.seekg(0);
  number = 0;
  double version = 0;
  while (next_line())
  {
    check_integers();
    if (line.rfind("$MeshFormat", 0) == 0 && next_line())
    {
      // "4.1 0 8": version, file type (1: binary), data size
      std::istringstream f(line);
      int type = 0;
      if (f >> version >> type && type != 0)
        return;
    }
    // gmsh 4.8 crashes on a physical-name line without its quoted name; every one of the
    // section's lines must be `dim tag "name"`.
    else if (line.rfind("$PhysicalNames", 0) == 0 && next_line())
    {
      long count = -1;
      std::istringstream(line) >> count;
      for (long k = 0; k < count && next_line(); ++k)
      {
        std::istringstream f(line);
        int dim = -1;
        long tag = 0;
        std::string rest;
        f >> dim >> tag;
        std::getline(f >> std::ws, rest);
        if (!f || dim < 0 || dim > 3 || rest.size() < 2 || rest.front() != '"' ||
            rest.find('"', 1) == std::string::npos)
          refuse("not a physical name (dim tag \"name\"): '" + line + "'");
      }
    }
    else if (line.rfind("$Entities", 0) == 0 && version >= 4.1 && next_line())
    {
      check_integers();
      const auto counts = tokens_of(line);
      if (counts.size() != 4 || !std::all_of(counts.begin(), counts.end(), is_integer))
        refuse("not the entity counts (nPoints nCurves nSurfaces nVolumes): '" + line + "'");
      for (int dim = 0; dim < 4; ++dim)
        for (long k = std::strtol(counts[dim].c_str(), nullptr, 10); k > 0 && next_line(); --k)
        {
          check_integers();
          if (!is_entity_line(tokens_of(line), dim == 0))
            refuse(std::string("not a ") + (dim == 0 ? "point" : "curve, surface or volume") +
                   " entity, or its counts do not match its tags: '" + line.substr(0, 80) + "'");
        }
    }
  }
}
} // namespace

void open_mesh_file(const std::string& path)
{
  check_mesh_headers(path);
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
