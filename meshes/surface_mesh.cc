#include "meshes/surface_mesh.h"

#include "common/input_error.h"
#include "meshes/gmsh_session.h"

#include <Eigen/LU>
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gmsh.h>
#include <map>
#include <sstream>
#include <unordered_map>

namespace chipflex::meshes
{
namespace
{
bool ends_with(const std::string& s, const std::string& tail)
{
  if (s.size() < tail.size())
    return false;
  std::string end = s.substr(s.size() - tail.size());
  std::transform(end.begin(), end.end(), end.begin(), ::tolower);
  return end == tail;
}

/// Vertices merged by their exact coordinates (STL repeats every corner per facet).
class VertexMerger
{
public:
  explicit VertexMerger(SurfaceMesh<3>& mesh) : mesh_(mesh) {}
  int operator()(const Eigen::Vector3d& x)
  {
    const auto [it, inserted] =
        ids_.emplace(std::array<double, 3>{x[0], x[1], x[2]}, int(mesh_.vertices.size()));
    if (inserted)
      mesh_.vertices.push_back(x);
    return it->second;
  }

private:
  SurfaceMesh<3>& mesh_;
  std::map<std::array<double, 3>, int> ids_;
};

void add_facet(SurfaceMesh<3>& mesh, VertexMerger& merge, const Eigen::Vector3d (&x)[3])
{
  const std::array<int, 3> f{merge(x[0]), merge(x[1]), merge(x[2])};
  if (f[0] != f[1] && f[1] != f[2] && f[0] != f[2]) // degenerate facets carry no area
    mesh.faces.push_back(f);
}

SurfaceMesh<3> read_stl(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path, "cannot open the STL file");
  const auto size = std::filesystem::file_size(path);
  SurfaceMesh<3> mesh;
  VertexMerger merge(mesh);
  char header[80] = {};
  in.read(header, 80);
  std::uint32_t n = 0;
  in.read(reinterpret_cast<char*>(&n), 4);
  if (in && size == 84 + 50 * std::uint64_t(n)) // binary: 80-byte header, count, facets
  {
    for (std::uint32_t k = 0; k < n; ++k)
    {
      float v[12];
      std::uint16_t attribute;
      in.read(reinterpret_cast<char*>(v), sizeof v);
      in.read(reinterpret_cast<char*>(&attribute), 2);
      if (!in)
        throw InputError(path, "binary STL ends inside facet " + std::to_string(k));
      const Eigen::Vector3d x[3] = {{v[3], v[4], v[5]}, {v[6], v[7], v[8]}, {v[9], v[10], v[11]}};
      add_facet(mesh, merge, x);
    }
  }
  else
  {
    in.clear();
    in.seekg(0);
    std::string word;
    int line_vertex = 0;
    Eigen::Vector3d x[3];
    in >> word;
    if (word != "solid")
      throw InputError(path, "neither a binary STL (size does not match its facet count) nor "
                             "an ASCII STL (does not begin with 'solid')");
    while (in >> word)
      if (word == "vertex")
      {
        if (line_vertex > 2)
          throw InputError(path, "a facet with more than three vertices");
        if (!(in >> x[line_vertex][0] >> x[line_vertex][1] >> x[line_vertex][2]))
          throw InputError(path, "a vertex line without three numbers");
        ++line_vertex;
      }
      else if (word == "endfacet")
      {
        if (line_vertex != 3)
          throw InputError(path, "a facet without three vertices");
        add_facet(mesh, merge, x);
        line_vertex = 0;
      }
  }
  if (mesh.faces.empty())
    throw InputError(path, "the STL file holds no facets");
  return mesh;
}

template <int dim>
SurfaceMesh<dim> read_msh(const std::string& path, const std::string& group)
{
  {
    std::ifstream probe(path);
    if (!probe)
      throw InputError(path, "cannot open the mesh file");
  }
  SurfaceMesh<dim> mesh;
  with_gmsh_model(
      path,
      [&]
      {
        open_mesh_file(path);
        std::vector<std::size_t> node_tags;
        std::vector<double> coords, parametric;
        gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
        std::unordered_map<std::size_t, int> vertex_of_tag;
        std::unordered_map<std::size_t, std::size_t> position;
        for (std::size_t i = 0; i < node_tags.size(); ++i)
          position[node_tags[i]] = i;
        auto vertex = [&](std::size_t tag)
        {
          const auto it = vertex_of_tag.find(tag);
          if (it != vertex_of_tag.end())
            return it->second;
          const auto p = position.find(tag);
          if (p == position.end())
            throw InputError(path, "an element refers to a missing node " + std::to_string(tag));
          Eigen::Matrix<double, dim, 1> x;
          for (int d = 0; d < dim; ++d)
            x[d] = coords[3 * p->second + d];
          vertex_of_tag[tag] = int(mesh.vertices.size());
          mesh.vertices.push_back(x);
          return vertex_of_tag[tag];
        };

        // Entities of dimension d (of the physical group, if one is named).
        auto entities = [&](int d)
        {
          std::vector<int> tags;
          if (group.empty())
          {
            gmsh::vectorpair all;
            gmsh::model::getEntities(all, d);
            for (const auto& e : all)
              tags.push_back(e.second);
            return tags;
          }
          gmsh::vectorpair groups;
          gmsh::model::getPhysicalGroups(groups, d);
          for (const auto& g : groups)
          {
            std::string name;
            gmsh::model::getPhysicalName(g.first, g.second, name);
            if (name == group)
              gmsh::model::getEntitiesForPhysicalGroup(g.first, g.second, tags);
          }
          return tags;
        };
        auto corners = [&](int type, int* element_dim)
        {
          std::string name;
          int order, n_nodes, n_primary;
          std::vector<double> local;
          gmsh::model::mesh::getElementProperties(type, name, *element_dim, order, n_nodes, local,
                                                  n_primary);
          return std::pair<int, int>(n_primary, n_nodes);
        };

        // Faces: the elements of dimension dim - 1.
        for (int tag : entities(dim - 1))
        {
          std::vector<int> types;
          std::vector<std::vector<std::size_t>> tags, nodes;
          gmsh::model::mesh::getElements(types, tags, nodes, dim - 1, tag);
          for (std::size_t k = 0; k < types.size(); ++k)
          {
            int element_dim = 0;
            const auto [n_corners, n_nodes] = corners(types[k], &element_dim);
            for (std::size_t e = 0; e * n_nodes < nodes[k].size(); ++e)
            {
              const std::size_t* c = &nodes[k][e * n_nodes];
              if constexpr (dim == 2)
                mesh.faces.push_back({vertex(c[0]), vertex(c[1])});
              else
              {
                mesh.faces.push_back({vertex(c[0]), vertex(c[1]), vertex(c[2])});
                if (n_corners == 4)
                  mesh.faces.push_back({vertex(c[0]), vertex(c[2]), vertex(c[3])});
              }
            }
          }
        }
        if (!mesh.faces.empty())
          return;

        // No faces: the boundary of the simplices of dimension dim, oriented outwards.
        std::map<std::array<std::size_t, dim>, std::pair<int, std::array<std::size_t, dim>>> seen;
        for (int tag : entities(dim))
        {
          std::vector<int> types;
          std::vector<std::vector<std::size_t>> tags, nodes;
          gmsh::model::mesh::getElements(types, tags, nodes, dim, tag);
          for (std::size_t k = 0; k < types.size(); ++k)
          {
            int element_dim = 0;
            const auto [n_corners, n_nodes] = corners(types[k], &element_dim);
            if (n_corners != dim + 1)
              throw InputError(path, "the boundary of non-simplex elements is not supported: "
                                     "give the mesh its faces (dimension " +
                                         std::to_string(dim - 1) + " elements)");
            for (std::size_t e = 0; e * n_nodes < nodes[k].size(); ++e)
            {
              std::array<std::size_t, dim + 1> c;
              std::copy_n(&nodes[k][e * n_nodes], dim + 1, c.begin());
              Eigen::Matrix<double, dim, dim> edges;
              for (int d = 0; d < dim; ++d)
                for (int i = 0; i < dim; ++i)
                  edges(i, d) =
                      coords[3 * position.at(c[d + 1]) + i] - coords[3 * position.at(c[0]) + i];
              if (edges.determinant() < 0)
                std::swap(c[0], c[1]);
              // Faces with the outward orientation of a positively oriented simplex.
              std::vector<std::array<std::size_t, dim>> faces;
              if constexpr (dim == 2)
                faces = {{c[0], c[1]}, {c[1], c[2]}, {c[2], c[0]}};
              else
                faces = {
                    {c[0], c[2], c[1]}, {c[0], c[1], c[3]}, {c[0], c[3], c[2]}, {c[1], c[2], c[3]}};
              for (const auto& f : faces)
              {
                auto key = f;
                std::sort(key.begin(), key.end());
                auto [it, inserted] = seen.emplace(key, std::make_pair(1, f));
                if (!inserted)
                  ++it->second.first;
              }
            }
          }
        }
        for (const auto& [key, entry] : seen)
          if (entry.first == 1)
          {
            std::array<int, dim> f;
            for (int d = 0; d < dim; ++d)
              f[d] = vertex(entry.second[d]);
            mesh.faces.push_back(f);
          }
      });
  if (mesh.faces.empty())
    throw InputError(path, group.empty() ? "the mesh holds no " + std::to_string(dim) + "D surface"
                                         : "no elements in the physical group '" + group + "'");
  return mesh;
}
} // namespace

template <int dim>
SurfaceMesh<dim> read_surface_mesh(const std::string& path, const std::string& group, bool flip)
{
  SurfaceMesh<dim> mesh;
  if (ends_with(path, ".stl"))
  {
    if constexpr (dim == 3)
    {
      if (!group.empty())
        throw InputError(path, "an STL file has no physical groups (asked for '" + group + "')");
      mesh = read_stl(path);
    }
    else
      throw InputError(path, "an STL surface in a 2D case (give a .msh with lines)");
  }
  else if (ends_with(path, ".msh"))
    mesh = read_msh<dim>(path, group);
  else
    throw InputError(path, "unknown surface format (expected .stl or .msh)");
  if (flip)
    for (auto& f : mesh.faces)
      std::swap(f[0], f[1]);
  return mesh;
}

template SurfaceMesh<2> read_surface_mesh<2>(const std::string&, const std::string&, bool);
template SurfaceMesh<3> read_surface_mesh<3>(const std::string&, const std::string&, bool);
} // namespace chipflex::meshes
