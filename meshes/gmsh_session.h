#pragma once
// One gmsh library session per process. gmsh::initialize/finalize may run only once,
// and gmsh prints to stdout by default; this keeps it quiet and turns its errors into
// InputError. Used by the mesh generators (meshes/) and the mesh reader (fem/).

#include <functional>
#include <string>

namespace chipflex::meshes
{
/// Initialises gmsh on first use (terminal output off); finalised at program exit.
void ensure_gmsh();

/// Inside with_gmsh_model: opens a mesh file into the model; InputError naming the file
/// if gmsh reports an error while reading it.
void open_mesh_file(const std::string& path);

/// Inside with_gmsh_model: writes the model's mesh (gmsh .msh 4.1, physical groups only)
/// atomically: to a temporary beside `path`, then renamed (InputError if that fails).
void write_mesh_file(const std::string& path);

/// Runs `action` on a fresh gmsh model; any gmsh failure becomes InputError(where, message).
void with_gmsh_model(const std::string& where, const std::function<void()>& action);
} // namespace chipflex::meshes
