#pragma once
// The structure of a gmsh .msh file, checked before gmsh reads it.
//
// libgmsh 4.8 trusts a .msh file: it reads counts with fscanf and sizes its arrays by them,
// reads a file that is not a mesh as a .geo script (a language with a `System` command),
// and corrupts its heap on some damaged sections. Fuzzing (docs/fuzzing.md) found each of
// these. A file that passes this check has the shape gmsh writes, so that what gmsh then
// reads is bounded by the file and its sections are where gmsh expects them.

#include <string>

namespace chipflex::meshes
{
/// Throws InputError ("FILE:LINE: problem") unless `path` is a text .msh file of format
/// 2.x or 4.1 whose sections are closed, whose counts match the lines that follow them and
/// whose integers are within what a file of its size can hold. Binary .msh files are
/// refused (gmsh's binary reader cannot be checked from outside): save them as text.
void check_msh_text(const std::string& path);
} // namespace chipflex::meshes
