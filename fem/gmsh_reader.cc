#include "fem/gmsh_reader.h"

#include "common/input_error.h"
#include "meshes/gmsh_session.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <gmsh.h>
#include <set>
#include <unordered_map>

namespace chipflex::fem
{
void GmshMeshData::require_group(const std::string& name, const std::string& why) const
{
  if (!face_groups.count(name) && !cell_groups.count(name))
  {
    std::string known;
    for (const auto& g : face_groups)
      known += (known.empty() ? "" : ", ") + g.first;
    for (const auto& g : cell_groups)
      known += (known.empty() ? "" : ", ") + g.first;
    throw InputError(path, "no physical group '" + name + "' (needed for " + why +
                               "; the mesh has: " + (known.empty() ? "none" : known) + ")");
  }
}

namespace
{
/// Corner node tags of all elements of dimension d on entity `tag` (-1: all entities).
struct Elements
{
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> nodes;
};

Elements elements_of(int d, int tag)
{
  Elements e;
  std::vector<std::vector<std::size_t>> element_tags;
  gmsh::model::mesh::getElements(e.types, element_tags, e.nodes, d, tag);
  return e;
}

/// For each node of a second-order element, given its reference coordinates (gmsh's
/// `localNodeCoord`), the corners whose linear shape functions do not vanish there: one
/// corner for a vertex, the ends of an edge, the corners of a face or of the cell for the
/// node in its middle. Returns fewer entries than nodes if two nodes share a sub-entity.
std::vector<std::vector<int>> midpoint_sub_entities(const std::vector<double>& local, int dim,
                                                    int corners, bool simplex)
{
  const std::size_t n_nodes = local.size() / dim;
  std::vector<std::vector<int>> result;
  std::set<std::vector<int>> seen;
  for (std::size_t n = 0; n < n_nodes; ++n)
  {
    std::vector<int> support;
    for (int c = 0; c < corners; ++c)
    {
      double value = 1;
      if (simplex)
      {
        // Barycentric coordinates on gmsh's reference simplex (corner 0 at the origin).
        double sum = 0;
        for (int d = 0; d < dim; ++d)
          sum += local[n * dim + d];
        value = c == 0 ? 1 - sum : local[n * dim + c - 1];
      }
      else
        // Multilinear shape functions on [-1, 1]^dim, the corners listed first.
        for (int d = 0; d < dim; ++d)
          value *= 0.5 * (1 + local[n * dim + d] * local[c * dim + d]);
      if (value > 1e-8)
        support.push_back(c);
    }
    if (seen.insert(support).second)
      result.push_back(support);
  }
  return result;
}

int corners_of(int type, int* element_dim, bool* simplex)
{
  std::string name;
  int order, n_nodes, n_primary;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(type, name, *element_dim, order, n_nodes, local,
                                          n_primary);
  *simplex = (*element_dim == 2 && n_primary == 3) || (*element_dim == 3 && n_primary == 4) ||
             *element_dim < 2;
  return n_primary;
}
} // namespace

GmshMeshData read_gmsh_mesh(const std::string& path)
{
  {
    std::ifstream probe(path);
    if (!probe)
      throw InputError(path, "cannot open mesh file");
  }
  GmshMeshData mesh;
  mesh.path = path;
  meshes::with_gmsh_model(
      path,
      [&]
      {
        meshes::open_mesh_file(path);

        for (int d = 3; d >= 2 && mesh.dim == 0; --d)
        {
          std::vector<int> types;
          std::vector<std::vector<std::size_t>> tags, nodes;
          gmsh::model::mesh::getElements(types, tags, nodes, d);
          for (const auto& t : tags)
            if (!t.empty())
              mesh.dim = d;
        }
        if (mesh.dim == 0)
          throw InputError(path, "no 2D or 3D elements (empty, truncated or not a mesh)");
        const int dim = mesh.dim;

        // Coordinates of all nodes by tag.
        std::vector<std::size_t> node_tags;
        std::vector<double> coords, parametric;
        gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
        std::unordered_map<std::size_t, std::size_t> position;
        for (std::size_t i = 0; i < node_tags.size(); ++i)
          position[node_tags[i]] = i;

        // Body cells, on every entity of dimension dim; vertices renumbered as first used.
        std::unordered_map<std::size_t, unsigned int> vertex_of_tag;
        auto vertex = [&](std::size_t tag) -> unsigned int
        {
          const auto it = vertex_of_tag.find(tag);
          if (it != vertex_of_tag.end())
            return it->second;
          const auto p = position.find(tag);
          if (p == position.end())
            throw InputError(path, "element refers to a missing node " + std::to_string(tag));
          const double* x = &coords[3 * p->second];
          if (dim == 2 && std::abs(x[2]) > 1e-12 * (1 + std::abs(x[0]) + std::abs(x[1])))
            throw InputError(path, "a 2D mesh must lie in the plane z = 0");
          mesh.vertices.push_back({x[0], x[1], x[2]});
          return vertex_of_tag[tag] = mesh.vertices.size() - 1;
        };
        auto node_position = [&](std::size_t tag) -> std::array<double, 3>
        {
          const auto p = position.find(tag);
          if (p == position.end())
            throw InputError(path, "element refers to a missing node " + std::to_string(tag));
          const double* x = &coords[3 * p->second];
          if (dim == 2 && std::abs(x[2]) > 1e-12 * (1 + std::abs(x[0]) + std::abs(x[1])))
            throw InputError(path, "a 2D mesh must lie in the plane z = 0");
          return {x[0], x[1], x[2]};
        };
        gmsh::vectorpair entities;
        gmsh::model::getEntities(entities, dim);
        std::map<int, std::pair<unsigned int, unsigned int>> cell_range; // entity -> [first, end)
        int cell_kind = -1, cell_order = -1;
        for (const auto& [d, tag] : entities)
        {
          const auto e = elements_of(d, tag);
          const unsigned int first = mesh.cells.size();
          for (std::size_t k = 0; k < e.types.size(); ++k)
          {
            int element_dim;
            bool simplex;
            const int corners = corners_of(e.types[k], &element_dim, &simplex);
            const bool supported =
                dim == 2 ? (corners == 3 || corners == 4) : (corners == 4 || corners == 8);
            if (!supported)
              throw InputError(path, "unsupported element type " + std::to_string(e.types[k]) +
                                         " (chipflex reads triangles, quadrilaterals, tetrahedra, "
                                         "hexahedra)");
            if (cell_kind != -1 && cell_kind != int(simplex))
              throw InputError(path, "mixed simplex and quad/hex cells are not supported");
            cell_kind = simplex;
            int n_nodes_per_element = 0, order = 1;
            std::vector<double> local;
            {
              std::string name;
              int ed, n_primary;
              gmsh::model::mesh::getElementProperties(e.types[k], name, ed, order,
                                                      n_nodes_per_element, local, n_primary);
            }
            if (order > 2)
              throw InputError(path, "cells of order " + std::to_string(order) +
                                         " (chipflex reads linear and quadratic meshes)");
            if (cell_order != -1 && cell_order != order)
              throw InputError(path, "mixed linear and quadratic cells are not supported");
            cell_order = order;
            const auto sub_entities = order == 2
                                          ? midpoint_sub_entities(local, dim, corners, simplex)
                                          : std::vector<std::vector<int>>();
            const int complete = simplex ? (dim + 1) * (dim + 2) / 2 : (dim == 2 ? 9 : 27);
            if (order == 2 && (n_nodes_per_element != complete ||
                               static_cast<int>(sub_entities.size()) != n_nodes_per_element))
              mesh.complete_second_order = false;
            for (std::size_t i = 0; i + n_nodes_per_element <= e.nodes[k].size();
                 i += n_nodes_per_element)
            {
              std::vector<unsigned int> cell(corners);
              for (int c = 0; c < corners; ++c)
                cell[c] = vertex(e.nodes[k][i + c]);
              for (int n = corners; mesh.complete_second_order && n < n_nodes_per_element; ++n)
              {
                std::vector<unsigned int> key;
                for (const int c : sub_entities[n])
                  key.push_back(cell[c]);
                std::sort(key.begin(), key.end());
                mesh.midpoint_nodes[key] = node_position(e.nodes[k][i + n]);
              }
              mesh.cells.push_back(std::move(cell));
            }
          }
          cell_range[tag] = {first, static_cast<unsigned int>(mesh.cells.size())};
        }
        mesh.simplex = cell_kind == 1;
        mesh.order = cell_order;

        gmsh::vectorpair groups;
        gmsh::model::getPhysicalGroups(groups);
        for (const auto& [d, group] : groups)
        {
          std::string name;
          gmsh::model::getPhysicalName(d, group, name);
          if (name.empty())
            name = std::to_string(group);
          std::vector<int> group_entities;
          gmsh::model::getEntitiesForPhysicalGroup(d, group, group_entities);
          if (d == dim)
          {
            auto& ids = mesh.cell_groups[name];
            for (int entity : group_entities)
              for (unsigned int c = cell_range[entity].first; c < cell_range[entity].second; ++c)
                ids.push_back(c);
          }
          else if (d == dim - 1)
          {
            auto& faces = mesh.face_groups[name];
            for (int entity : group_entities)
            {
              const auto e = elements_of(d, entity);
              for (std::size_t k = 0; k < e.types.size(); ++k)
              {
                int element_dim;
                bool simplex;
                const int corners = corners_of(e.types[k], &element_dim, &simplex);
                std::string n;
                int ed, order, n_nodes, n_primary;
                std::vector<double> local;
                gmsh::model::mesh::getElementProperties(e.types[k], n, ed, order, n_nodes, local,
                                                        n_primary);
                for (std::size_t i = 0; i + n_nodes <= e.nodes[k].size(); i += n_nodes)
                {
                  std::vector<unsigned int> face(corners);
                  for (int c = 0; c < corners; ++c)
                  {
                    const auto it = vertex_of_tag.find(e.nodes[k][i + c]);
                    if (it == vertex_of_tag.end())
                      throw InputError(path, "physical group '" + name +
                                                 "' has a face that is not on the body's cells");
                    face[c] = it->second;
                  }
                  faces.push_back(std::move(face));
                }
              }
            }
          }
        }
      });
  return mesh;
}
} // namespace chipflex::fem
