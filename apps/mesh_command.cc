// `chipflex mesh gate|plate|chip`: structured (default) or simplex gmsh meshes of the bodies
// chipflex reduces, with the physical groups body, clamp, tip and skin (gate, plate) or
// body, skin, start and end (chip, meshes/chip_mesher.h).
//
// Coordinates (documented in docs/body_file_format.md):
//   gate  2D: x in [0, thickness], y in [0, length]; clamp at the top (y = length), tip at
//             the bottom (y = 0) - the Antoci gate hangs from its clamp. 3D (--depth D):
//             the same, extruded over z in [0, D].
//   plate 3D: x in [0, length], y in [0, width], z in [0, thickness]; clamp at x = 0, tip at
//             x = length.

#include "apps/commands.h"
#include "common/command_line.h"
#include "common/input_error.h"
#include "meshes/block_mesher.h"
#include "meshes/chip_mesher.h"

#include <iostream>

namespace chipflex::apps
{
namespace
{
int mesh_chip(const Arguments& args)
{
  common::CommandLine cl(
      "chipflex mesh chip --shape helical|spiral|arc|ribbon -o MESH.msh [options]",
      "Mesh a machining chip: a width x thickness section swept along the chip's\n"
      "centre curve, structured hexahedra (27-node quadratic by default) with --layers\n"
      "elements through the thickness. Physical groups body, skin, start, end (a ring,\n"
      "--shape arc --arc-angle 360, has no ends). Coordinates: docs/chips.md.");
  cl.add_positional("KIND", "chip");
  cl.add_option("--output", "FILE", "output mesh file (.msh)", "", true);
  cl.add_alias("-o", "--output");
  cl.add_option("--shape", "SHAPE", "helical, spiral, arc (360 degrees: a ring) or ribbon", "",
                true);
  cl.add_option("--width", "M", "section width (in the curl plane / radial)", "0.002");
  cl.add_option("--thickness", "M", "section thickness (along the curl axis)", "0.0002");
  cl.add_option("--curl-radius", "M",
                "radius of the centre curve (spiral: at its start); above width / 2", "0.002");
  cl.add_option("--pitch", "M",
                "per turn: helical axial advance (default 0.001), spiral radial growth "
                "(default 2 x width)");
  cl.add_option("--turns", "N", "helical and spiral: number of turns", "2");
  cl.add_option("--arc-angle", "DEG", "arc: angle of the arc, (0, 360]", "180");
  cl.add_option("--length", "M", "ribbon: length", "0.01");
  cl.add_option("--size", "M",
                "element edge length along the chip and across the width "
                "(default: width / 4)");
  cl.add_option("--layers", "N", "elements through the thickness, at least 2", "2");
  cl.add_option("--order", "N", "1: 8-node, 2: 27-node (curved) hexahedra", "2");
  if (!cl.parse(args))
    return 0;

  meshes::ChipMeshSpec spec;
  spec.shape = meshes::parse_chip_shape(cl.get("--shape"), "--shape");
  spec.width = cl.get_double("--width");
  spec.thickness = cl.get_double("--thickness");
  spec.curl_radius = cl.get_double("--curl-radius");
  spec.turns = cl.get_double("--turns");
  spec.arc_angle = cl.get_double("--arc-angle");
  spec.length = cl.get_double("--length");
  spec.pitch = cl.has("--pitch")                                   ? cl.get_double("--pitch")
               : spec.shape == meshes::ChipMeshSpec::Shape::spiral ? 2 * spec.width
                                                                   : 0.001;
  spec.size = cl.has("--size") ? cl.get_double("--size") : spec.width / 4;
  spec.layers = static_cast<int>(cl.get_int("--layers"));
  spec.order = static_cast<int>(cl.get_int("--order"));

  const std::string output = cl.get("--output");
  const auto summary = meshes::write_chip_mesh(spec, output);
  std::cout << "wrote " << output << ": " << cl.get("--shape")
            << (meshes::chip_is_closed(spec) ? " (closed ring)" : "") << " chip, "
            << summary.n_elements << (spec.order == 2 ? " 27-node" : " 8-node") << " hexahedra, "
            << summary.n_nodes << " nodes, volume " << meshes::chip_volume(spec)
            << " m^3, centre length " << meshes::chip_centre_length(spec) << " m\n";
  return 0;
}
} // namespace

int mesh_command(const Arguments& args)
{
  if (!args.empty() && args[0] == "chip")
    return mesh_chip(args);
  common::CommandLine cl(
      "chipflex mesh gate|plate|chip -o MESH.msh [options]",
      "Generate a gmsh .msh 4.1 mesh with physical groups body, clamp, tip, skin and\n"
      "the sides xmin, xmax, ymin, ymax (, zmin, zmax).\n"
      "gate: 2D rectangle thickness (x) by length (y), clamped at the top end;\n"
      "      with --depth a 3D plate. plate: 3D strip along x, clamped at x = 0.\n"
      "chip: a machining chip (see `chipflex mesh chip --help`).");
  cl.add_positional("KIND", "gate, plate or chip");
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
    throw InputError("chipflex mesh " + kind, "unknown kind (expected gate, plate or chip)");

  const std::string output = cl.get("--output");
  const auto n = meshes::write_block_mesh(spec, output);
  std::cout << "wrote " << output << ": " << spec.dim << "D " << kind << ", " << n
            << (spec.simplex ? (spec.dim == 2 ? " triangles" : " tetrahedra")
                             : (spec.dim == 2 ? " quadrilaterals" : " hexahedra"))
            << "\n";
  return 0;
}
} // namespace chipflex::apps
