// Body kind `rigid`: a rigid body of any shape, 2D or 3D. Its shape is a primitive (box,
// cylinder, sphere, with exact mass properties), a closed surface from a mesh file
// (gmsh .msh: the boundary of a surface/volume mesh or its faces; STL), or the skin of a
// body file (with the file's mass properties). Free, or fixed in space when clamped.

#include "apps/body_kinds/body_kind.h"
#include "common/input_error.h"
#include "common/reduced_body_file.h"
#include "coupling/multibody_coupled_body.h"
#include "coupling/rigid_shapes.h"
#include "mbs/rigid_body.h"
#include "meshes/surface_mesh.h"

namespace chipflex::apps
{
namespace
{
class RigidKind : public AnyDimensionKind<RigidKind>
{
public:
  std::string name() const override { return "rigid"; }
  std::string description() const override
  {
    return "rigid (box, cylinder, sphere, a closed mesh surface or a body file's skin)";
  }

  void declare(BodyKeyDeclarations& keys) const override
  {
    keys.declare("shape", "box", "box|cylinder|sphere|mesh|body file",
                 "box (size), cylinder (radius, cylinder length; 2D: a disc), sphere (radius; "
                 "2D: a disc), mesh (a closed surface from `mesh`) or body file (its skin and "
                 "mass properties). Primitives are centred on the frame origin; a mesh or body "
                 "file keeps its own coordinates as frame coordinates.");
    keys.declare("size", "0.05", "text",
                 "Box edge lengths along the frame axes (one per axis, or one for a square or "
                 "cube), m.");
    keys.declare("radius", "0.025", "double >= 0", "Cylinder or sphere radius, m.");
    keys.declare("cylinder length", "0.05", "double >= 0", "Along the frame's z axis, m.");
    keys.declare("density", "", "text", "kg/m^3 (required: no default).");
    keys.declare("mesh", "", "text",
                 "gmsh .msh (2D: lines or the boundary of a surface mesh; 3D: triangles or the "
                 "boundary of a tetrahedral mesh) or STL (3D) file, frame coordinates, m.");
    keys.declare("mesh group", "", "text", "Physical group of `mesh` to take; empty: all.");
    keys.declare("body file", "", "text", "HDF5 body file from `chipflex reduce`.");
    keys.declare("skin spacing", "0", "double >= 0",
                 "Primitives: largest distance of skin nodes, m; 0: the fluid's spacing.");
  }

private:
  template <int dim>
  static coupling::RigidShape<dim> shape(const BodyKeys& keys, const BodyContext<dim>& context)
  {
    const std::string shape = keys.text("shape");
    double spacing = keys.number("skin spacing");
    if (!(spacing > 0))
      spacing = context.particle_spacing;
    if (shape == "box")
    {
      const auto v = keys.numbers("size");
      Eigen::Matrix<double, dim, 1> size =
          Eigen::Matrix<double, dim, 1>::Constant(v.empty() ? 0 : v[0]);
      if (v.size() > 1)
        size = keys.vector<dim>("size");
      if (!(size.minCoeff() > 0))
        throw InputError(keys.at("size"), "needs " + std::to_string(dim) + " positive lengths");
      return coupling::box_shape<dim>(size, keys.positive("density"), spacing);
    }
    if (shape == "cylinder")
      return coupling::cylinder_shape<dim>(keys.positive("radius"),
                                           dim == 3 ? keys.positive("cylinder length") : 0,
                                           keys.positive("density"), spacing);
    if (shape == "sphere")
      return coupling::sphere_shape<dim>(keys.positive("radius"), keys.positive("density"),
                                         spacing);
    if (shape == "mesh")
    {
      const std::string file = keys.file("mesh");
      auto mesh = meshes::read_surface_mesh<dim>(file, keys.text("mesh group"));
      return coupling::closed_surface_shape<dim>(mesh.vertices, mesh.faces,
                                                 keys.positive("density"), file);
    }
    // The skin of a body file, with the file's mass properties (its FE mass matrix).
    const std::string file = keys.file("body file");
    const ReducedBodyData data = read_reduced_body(file);
    if (data.dim != dim)
      throw InputError(file, "a " + std::to_string(data.dim) + "D body file in a " +
                                 std::to_string(dim) + "D case");
    coupling::RigidShape<dim> s;
    std::vector<int> skin_index(data.nodes.rows(), -1);
    for (int n : data.skin_nodes)
    {
      skin_index[n] = int(s.nodes.size());
      s.nodes.push_back(data.nodes.row(n).transpose());
    }
    for (int f = 0; f < data.skin_faces.rows(); ++f)
    {
      std::array<int, dim> face;
      for (int k = 0; k < dim; ++k)
        face[k] = skin_index.at(data.skin_faces(f, k));
      s.faces.push_back(face);
    }
    s.mass = data.mass;
    s.centre_of_mass = data.center_of_mass;
    s.inertia = data.inertia_tensor;
    return s;
  }

public:
  template <int dim>
  static std::unique_ptr<coupling::CoupledBody<dim>> make(const BodyKeys& keys,
                                                          const BodyContext<dim>& context)
  {
    const auto s = shape<dim>(keys, context);
    auto system = make_body_system(context);
    auto body = mbs::make_rigid_body<dim>(
        mbs::rigid_body_data<dim>(s.mass, s.centre_of_mass, s.inertia, s.nodes, s.faces));
    place_body(*body, context.placement);
    auto* skin = body.get();
    system->add_body(std::move(body));
    const Eigen::Matrix<double, dim, 1> com = s.centre_of_mass;
    return std::make_unique<coupling::MultibodyCoupledBody<dim>>(
        "rigid", std::move(system), *skin, context.max_step,
        [com](const mbs::MultibodySystem<dim>& system)
        { return Eigen::Matrix<double, dim, 1>(system.body(0).point_position(com)); });
  }
};

const BodyKindRegistration registration(std::make_unique<RigidKind>());
} // namespace
} // namespace chipflex::apps
