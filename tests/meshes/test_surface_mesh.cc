// Surfaces from files (meshes/surface_mesh.h): STL (ASCII and binary) and gmsh meshes
// (their faces, or the boundary of their elements) give the same closed surface, checked
// by the exact volume of the polyhedron they bound (coupling/rigid_shapes.h).

#include "common/input_error.h"
#include "coupling/rigid_shapes.h"
#include "meshes/gmsh_session.h"
#include "meshes/surface_mesh.h"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gmsh.h>
#include <unistd.h>

using namespace chipflex;
namespace fs = std::filesystem;

namespace
{
/// A 0.2 x 0.3 x 0.4 box as 12 outward facets.
std::vector<std::array<Eigen::Vector3d, 3>> box_facets()
{
  const Eigen::Vector3d size(0.2, 0.3, 0.4);
  auto corner = [&](int i)
  { return Eigen::Vector3d(size[0] * (i & 1), size[1] * ((i >> 1) & 1), size[2] * (i >> 2)); };
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<std::array<Eigen::Vector3d, 3>> f;
  for (const auto& q : quads)
  {
    f.push_back({corner(q[0]), corner(q[1]), corner(q[2])});
    f.push_back({corner(q[0]), corner(q[2]), corner(q[3])});
  }
  return f;
}

double volume_of(const meshes::SurfaceMesh<3>& m)
{
  return coupling::closed_surface_shape<3>(m.vertices, m.faces, 1, "test").volume;
}

struct TempDir
{
  fs::path path = fs::temp_directory_path() / ("chipflex_surface_" + std::to_string(::getpid()));
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
};
} // namespace

TEST_CASE("ASCII and binary STL give the same closed box")
{
  TempDir tmp;
  const auto facets = box_facets();
  {
    std::ofstream a(tmp.path / "box.stl");
    a << "solid box\n";
    for (const auto& f : facets)
    {
      a << " facet normal 0 0 0\n  outer loop\n";
      for (const auto& x : f)
        a << "   vertex " << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
      a << "  endloop\n endfacet\n";
    }
    a << "endsolid box\n";
  }
  {
    std::ofstream b(tmp.path / "binary.stl", std::ios::binary);
    char header[80] = "solid but binary";
    b.write(header, 80);
    const std::uint32_t n = facets.size();
    b.write(reinterpret_cast<const char*>(&n), 4);
    for (const auto& f : facets)
    {
      float v[12] = {0, 0, 0};
      for (int k = 0; k < 3; ++k)
        for (int d = 0; d < 3; ++d)
          v[3 + 3 * k + d] = float(f[k][d]);
      b.write(reinterpret_cast<const char*>(v), sizeof v);
      const std::uint16_t attribute = 0;
      b.write(reinterpret_cast<const char*>(&attribute), 2);
    }
  }
  const auto ascii = meshes::read_surface_mesh<3>((tmp.path / "box.stl").string());
  const auto binary = meshes::read_surface_mesh<3>((tmp.path / "binary.stl").string());
  CHECK(ascii.vertices.size() == 8);
  CHECK(ascii.faces.size() == 12);
  CHECK(binary.vertices.size() == 8);
  CHECK(volume_of(ascii) == Approx(0.024).epsilon(1e-12));
  CHECK(volume_of(binary) == Approx(0.024).epsilon(1e-6)); // float coordinates
  // Flipped faces point into the box: the fluid would be inside.
  const auto flipped = meshes::read_surface_mesh<3>((tmp.path / "box.stl").string(), "", true);
  const auto& f = flipped.faces[0];
  const Eigen::Vector3d n = (flipped.vertices[f[1]] - flipped.vertices[f[0]])
                                .cross(flipped.vertices[f[2]] - flipped.vertices[f[0]]);
  CHECK(n.dot(Eigen::Vector3d(0.1, 0.15, 0.2) - flipped.vertices[f[0]]) > 0);
  {
    std::ofstream bad(tmp.path / "bad.stl");
    bad << "not an stl\n";
  }
  CHECK_THROWS_AS(meshes::read_surface_mesh<3>((tmp.path / "bad.stl").string()), InputError);
  CHECK_THROWS_AS(meshes::read_surface_mesh<3>((tmp.path / "box.obj").string()), InputError);
}

TEST_CASE("a gmsh volume mesh: its surface triangles, or its boundary, bound the box")
{
  TempDir tmp;
  const std::string with_faces = (tmp.path / "faces.msh").string();
  const std::string volume_only = (tmp.path / "volume.msh").string();
  for (const bool faces : {true, false})
    meshes::with_gmsh_model(
        "test",
        [&]
        {
          gmsh::model::occ::addBox(0, 0, 0, 0.2, 0.3, 0.4);
          gmsh::model::occ::synchronize();
          gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {1}), "body");
          if (faces)
            gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {1, 2, 3, 4, 5, 6}),
                                         "skin");
          gmsh::option::setNumber("Mesh.MeshSizeMax", 0.1);
          gmsh::model::mesh::generate(3);
          gmsh::write(faces ? with_faces : volume_only);
        });
  const auto skin = meshes::read_surface_mesh<3>(with_faces, "skin");
  CHECK(volume_of(skin) == Approx(0.024).epsilon(1e-12));
  const auto boundary = meshes::read_surface_mesh<3>(volume_only);
  CHECK(volume_of(boundary) == Approx(0.024).epsilon(1e-12));
  CHECK(boundary.faces.size() == skin.faces.size());
  CHECK_THROWS_AS(meshes::read_surface_mesh<3>(with_faces, "no such group"), InputError);
}

TEST_CASE("a gmsh 2D mesh: its boundary lines bound the rectangle")
{
  TempDir tmp;
  const std::string path = (tmp.path / "plane.msh").string();
  meshes::with_gmsh_model("test",
                          [&]
                          {
                            gmsh::model::occ::addRectangle(0, 0, 0, 0.5, 0.2);
                            gmsh::model::occ::synchronize();
                            gmsh::option::setNumber("Mesh.MeshSizeMax", 0.05);
                            gmsh::model::mesh::generate(2);
                            gmsh::write(path);
                          });
  const auto outline = meshes::read_surface_mesh<2>(path);
  const auto s = coupling::closed_surface_shape<2>(outline.vertices, outline.faces, 1, "plane");
  CHECK(s.volume == Approx(0.1).epsilon(1e-12));
  CHECK((s.centre_of_mass - Eigen::Vector2d(0.25, 0.1)).norm() < 1e-12);
}
