#pragma once
// Generator for machining chips (`chipflex mesh chip`): a rectangular section, width w by
// thickness t, swept along the chip's centre curve, meshed with structured hexahedra
// (quadratic by default) with at least two layers through the thickness.
//
// Shapes and coordinates (all lengths in m; the chip's broad faces carry the width, its
// thickness is the short side of the section):
//   ribbon   straight: x in [0, L] along the chip, y in [-w/2, w/2], z in [-t/2, t/2].
//   arc      centre curve a circle of radius R (the curl radius) about the z axis, from
//            the x axis (angle 0) counter-clockwise to the arc angle; the width lies in
//            the curl plane (radius from R - w/2 to R + w/2), the thickness along z in
//            [-t/2, t/2]. An arc of 360 degrees closes into a ring (no ends).
//   spiral   flat Archimedean spiral in the plane z = 0: centre radius r = R + p phi/(2 pi)
//            for phi in [0, 2 pi turns] (p: the radial pitch, growth per turn); width
//            radial (r +- w/2), thickness along z.
//   helical  centre curve the helix (R cos phi, R sin phi, p phi/(2 pi)), phi in
//            [0, 2 pi turns] (p: the axial pitch, advance per turn); the section lies in
//            the curve's normal plane, the width along the principal normal (towards the
//            axis), the thickness along the binormal (Frenet sweep).
//
// Physical groups written (gmsh .msh 4.1, names kept):
//   body  (3)  the whole chip
//   skin  (2)  its whole boundary (overlaps the ends)
//   start (2)  the end face at the start of the centre curve (x = 0, angle 0); not for a ring
//   end   (2)  the end face at its end; not for a ring

#include <string>

namespace chipflex::meshes
{
struct ChipMeshSpec
{
  enum class Shape
  {
    ribbon,
    arc,
    spiral,
    helical
  };
  Shape shape = Shape::arc;
  double width = 0;       ///< w, m
  double thickness = 0;   ///< t, m
  double curl_radius = 0; ///< R, m: the centre curve's radius (spiral: at its start)
  double pitch = 0;       ///< m per turn: helical axial advance, spiral radial growth
  double turns = 0;       ///< helical, spiral
  double arc_angle = 0;   ///< arc, degrees in (0, 360]; 360 is a closed ring
  double length = 0;      ///< ribbon, m
  double size = 0;        ///< element edge length along the chip and across its width, m
  int layers = 2;         ///< elements through the thickness, at least 2
  int order = 2;          ///< 1 (8-node) or 2 (27-node, curved) hexahedra
};

/// "ribbon", "arc", "spiral", "helical" -> Shape; throws InputError(where, ...) otherwise.
ChipMeshSpec::Shape parse_chip_shape(const std::string& name, const std::string& where);

/// Throws InputError naming the option for impossible parameters: a non-positive width,
/// thickness, length, size or turn count; a curl radius not above half the width; a pitch
/// that makes adjacent turns overlap; an arc angle outside (0, 360]; a mesh size larger
/// than the chip; fewer than 2 layers.
void check_chip_spec(const ChipMeshSpec& spec);

/// Length of the chip's centre curve, m (exact).
double chip_centre_length(const ChipMeshSpec& spec);

/// The chip's exact volume, m^3 (w t times the centre length for the ribbon, arc and the
/// Frenet-swept helix; w t times the integral of r dphi for the radially-offset spiral).
double chip_volume(const ChipMeshSpec& spec);

/// True for an arc of 360 degrees: a ring without ends.
bool chip_is_closed(const ChipMeshSpec& spec);

struct ChipMeshSummary
{
  std::size_t n_elements = 0; ///< hexahedra
  std::size_t n_nodes = 0;    ///< mesh nodes (with the second-order ones)
};

/// Checks the spec, meshes the chip and writes it atomically to `path` (gmsh .msh 4.1).
ChipMeshSummary write_chip_mesh(const ChipMeshSpec& spec, const std::string& path);
} // namespace chipflex::meshes
