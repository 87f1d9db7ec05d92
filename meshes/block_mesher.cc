#include "meshes/block_mesher.h"

#include "common/input_error.h"
#include "meshes/gmsh_session.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <gmsh.h>
#include <unistd.h>

namespace chipflex::meshes
{
namespace
{
/// Entities of dimension `d` lying in the (slightly inflated) box [lo, hi].
std::vector<int> entities_in(int d, std::array<double, 3> lo, std::array<double, 3> hi, double eps)
{
  gmsh::vectorpair tags;
  gmsh::model::getEntitiesInBoundingBox(lo[0] - eps, lo[1] - eps, lo[2] - eps, hi[0] + eps,
                                        hi[1] + eps, hi[2] + eps, tags, d);
  std::vector<int> result;
  for (const auto& t : tags)
    result.push_back(t.second);
  return result;
}

/// Makes every curve, surface and volume transfinite with ceil(length / size) elements,
/// so that the mesh is a structured grid of quads (2D) or hexahedra (3D).
void make_structured(const BlockMeshSpec& spec)
{
  gmsh::vectorpair curves;
  gmsh::model::getEntities(curves, 1);
  for (const auto& c : curves)
  {
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(1, c.second, x0, y0, z0, x1, y1, z1);
    // OpenCASCADE pads bounding boxes by ~1e-7 on each side: without the slack of 1 %
    // of an element, a 5 mm edge at 1.25 mm would get 5 elements instead of 4.
    const double length = std::max({x1 - x0, y1 - y0, z1 - z0});
    const int n = std::max(1, static_cast<int>(std::ceil(length / spec.size - 0.01)));
    gmsh::model::mesh::setTransfiniteCurve(c.second, n + 1);
  }
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  for (const auto& s : surfaces)
  {
    gmsh::model::mesh::setTransfiniteSurface(s.second);
    gmsh::model::mesh::setRecombine(2, s.second);
  }
  gmsh::vectorpair volumes;
  gmsh::model::getEntities(volumes, 3);
  for (const auto& v : volumes)
    gmsh::model::mesh::setTransfiniteVolume(v.second);
}
} // namespace

std::size_t write_block_mesh(const BlockMeshSpec& spec, const std::string& path)
{
  const int dim = spec.dim;
  for (int d = 0; d < dim; ++d)
    if (!(spec.extent[d] > 0))
      throw InputError("mesh dimensions", "every extent must be positive");
  if (!(spec.size > 0))
    throw InputError("--size", "must be positive");
  const double longest = *std::max_element(spec.extent.begin(), spec.extent.begin() + dim);
  if (longest / spec.size > 5000)
    throw InputError("--size", "too small for the body (over 5000 elements along an edge)");

  std::size_t n_elements = 0;
  with_gmsh_model(
      path,
      [&]
      {
        gmsh::model::add("chipflex_block");
        int body;
        if (dim == 2)
          body = gmsh::model::occ::addRectangle(0, 0, 0, spec.extent[0], spec.extent[1]);
        else
          body = gmsh::model::occ::addBox(0, 0, 0, spec.extent[0], spec.extent[1], spec.extent[2]);
        gmsh::model::occ::synchronize();

        std::array<double, 3> lo{0, 0, 0}, hi = spec.extent;
        if (dim == 2)
          hi[2] = 0;
        // Inflation of the selection boxes: above OpenCASCADE's bounding-box padding (1e-7),
        // far below the thinnest extent.
        const double thinnest = *std::min_element(spec.extent.begin(), spec.extent.begin() + dim);
        const double eps = std::max(1e-3 * thinnest, 1e-6);
        const int a = spec.long_axis;
        auto end_face = [&](bool at_max)
        {
          auto l = lo, h = hi;
          (at_max ? l : h)[a] = at_max ? hi[a] : lo[a];
          return entities_in(dim - 1, l, h, eps);
        };
        gmsh::model::setPhysicalName(dim, gmsh::model::addPhysicalGroup(dim, {body}), "body");
        gmsh::model::setPhysicalName(
            dim - 1, gmsh::model::addPhysicalGroup(dim - 1, end_face(spec.clamp_at_max)), "clamp");
        gmsh::model::setPhysicalName(
            dim - 1, gmsh::model::addPhysicalGroup(dim - 1, end_face(!spec.clamp_at_max)), "tip");
        gmsh::model::setPhysicalName(
            dim - 1, gmsh::model::addPhysicalGroup(dim - 1, entities_in(dim - 1, lo, hi, eps)),
            "skin");
        // Each side by its position, e.g. xmin = the face at x = 0 (the gate's upstream face).
        const char* axis_name[] = {"x", "y", "z"};
        for (int axis = 0; axis < dim; ++axis)
          for (const bool at_max : {false, true})
          {
            auto l = lo, h = hi;
            (at_max ? l : h)[axis] = at_max ? hi[axis] : lo[axis];
            gmsh::model::setPhysicalName(
                dim - 1, gmsh::model::addPhysicalGroup(dim - 1, entities_in(dim - 1, l, h, eps)),
                std::string(axis_name[axis]) + (at_max ? "max" : "min"));
          }

        if (spec.simplex)
        {
          gmsh::option::setNumber("Mesh.MeshSizeMax", spec.size);
          gmsh::option::setNumber("Mesh.MeshSizeMin", 0.5 * spec.size);
        }
        else
          make_structured(spec);
        gmsh::model::mesh::generate(dim);

        std::vector<int> types;
        std::vector<std::vector<std::size_t>> tags, nodes;
        gmsh::model::mesh::getElements(types, tags, nodes, dim);
        for (const auto& t : tags)
          n_elements += t.size();

        write_mesh_file(path);
      });
  return n_elements;
}
} // namespace chipflex::meshes
