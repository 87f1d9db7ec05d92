// `chipflex mesh gate|plate`: structured (default) or simplex gmsh meshes of the bodies
// chipflex reduces, with the physical groups body, clamp, tip and skin.
//
// Coordinates (documented in docs/body_file_format.md):
//   gate  2D: x in [0, thickness], y in [0, length]; clamp at the top (y = length), tip at
//             the bottom (y = 0) - the Antoci gate hangs from its clamp. 3D (--depth D):
//             the same, extruded over z in [0, D].
//   plate 3D: x in [0, length], y in [0, width], z in [0, thickness]; clamp at x = 0, tip at
//             x = length.

#include "apps/command_line.h"
#include "apps/commands.h"
#include "common/input_error.h"
#include "meshes/block_mesher.h"

#include <iostream>

namespace chipflex::apps
{
int mesh_command(const Arguments& args)
{
  CommandLine cl("chipflex mesh gate|plate -o MESH.msh [options]",
                 "Generate a gmsh .msh 4.1 mesh with physical groups body, clamp, tip, skin and\n"
                 "the sides xmin, xmax, ymin, ymax (, zmin, zmax).\n"
                 "gate: 2D rectangle thickness (x) by length (y), clamped at the top end;\n"
                 "      with --depth a 3D plate. plate: 3D strip along x, clamped at x = 0.");
  cl.add_positional("KIND", "gate or plate");
  cl.add_option("--output", "FILE", "output mesh file (.msh)", "", true);
  cl.add_alias("-o", "--output");
  cl.add_option("--length", "M", "length, clamp to tip (gate 0.079, plate 0.1)");
  cl.add_option("--thickness", "M", "thickness (gate 0.005, plate 0.002)");
  cl.add_option("--width", "M", "plate width along y", "0.01");
  cl.add_option("--depth", "M", "gate only: extrude to a 3D plate of this depth (z)");
  cl.add_option("--size", "M",
                "element edge length (default: thickness / 4 for the gate, "
                "thickness / 2 for the plate)");
  cl.add_flag("--simplex", "unstructured triangles/tetrahedra instead of quads/hexahedra");
  if (!cl.parse(args))
    return 0;

  const std::string kind = cl.get("KIND");
  meshes::BlockMeshSpec spec;
  spec.simplex = cl.flag("--simplex");
  auto value = [&](const std::string& name, double fallback)
  {
    const double v = cl.has(name) ? cl.get_double(name) : fallback;
    if (!(v > 0))
      throw InputError(name, "must be positive, got " + std::to_string(v));
    return v;
  };
  if (kind == "gate")
  {
    const double length = value("--length", 0.079), thickness = value("--thickness", 0.005);
    spec.dim = cl.has("--depth") ? 3 : 2;
    spec.extent = {thickness, length, spec.dim == 3 ? value("--depth", 0) : 0.};
    spec.long_axis = 1;
    spec.clamp_at_max = true;
    spec.size = value("--size", thickness / 4);
  }
  else if (kind == "plate")
  {
    if (cl.has("--depth"))
      throw InputError("--depth", "only for `chipflex mesh gate` (a plate is 3D already)");
    const double length = value("--length", 0.1), thickness = value("--thickness", 0.002);
    spec.dim = 3;
    spec.extent = {length, value("--width", 0.01), thickness};
    spec.long_axis = 0;
    spec.clamp_at_max = false;
    spec.size = value("--size", thickness / 2);
  }
  else
    throw InputError("chipflex mesh " + kind, "unknown kind (expected gate or plate)");

  const std::string output = cl.get("--output");
  const auto n = meshes::write_block_mesh(spec, output);
  std::cout << "wrote " << output << ": " << spec.dim << "D " << kind << ", " << n
            << (spec.simplex ? (spec.dim == 2 ? " triangles" : " tetrahedra")
                             : (spec.dim == 2 ? " quadrilaterals" : " hexahedra"))
            << "\n";
  return 0;
}
} // namespace chipflex::apps
