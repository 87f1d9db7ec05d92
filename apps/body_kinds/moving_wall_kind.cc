// Body kind `moving wall`: a wall with a prescribed motion (coupling/prescribed_motion_body.h).
// Its surface, a polyline (2D) or a surface mesh (gmsh .msh or STL, 2D lines or 3D
// triangles) in frame coordinates, is placed by the body's position and rotation; it then
// translates with the body's `velocity` and turns with its `angular velocity` about the
// frame origin, whatever the fluid does. It reports the force and the torque it takes
// (probes: <name>_force_*_N, <name>_torque_Nm), e.g. a turning drill's borehole wall.

#include "apps/body_kinds/body_kind.h"
#include "common/input_error.h"
#include "coupling/prescribed_motion_body.h"
#include "meshes/surface_mesh.h"

namespace chipflex::apps
{
namespace
{
class MovingWallKind : public AnyDimensionKind<MovingWallKind>
{
public:
  std::string name() const override { return "moving wall"; }
  std::string description() const override
  {
    return "moving wall (a surface with prescribed translation and rotation)";
  }

  void declare(BodyKeyDeclarations& keys) const override
  {
    keys.declare("outline", "", "text",
                 "2D: polyline x1, y1, x2, y2, ... in frame coordinates, m; the fluid lies on "
                 "the right of travel. Ending at its first point closes it (a closed skin: "
                 "fluid starting inside is removed).");
    keys.declare("surface", "", "text",
                 "gmsh .msh or STL surface in frame coordinates (instead of `outline`), m.");
    keys.declare("surface group", "", "text", "Physical group of `surface`; empty: all.");
    keys.declare("flip normals", "false", "bool",
                 "Reverse the faces of `surface` (the fluid lies on the side of the normal).");
    keys.declare("in place", "false", "bool",
                 "The surface keeps its place, only its velocity follows the motion: for a "
                 "surface the motion maps onto itself (a cylinder turning about its axis, "
                 "a belt), which may then be given only where it meets the fluid.");
  }

  template <int dim>
  static std::unique_ptr<coupling::CoupledBody<dim>> make(const BodyKeys& keys,
                                                          const BodyContext<dim>& context)
  {
    using Vector = Eigen::Matrix<double, dim, 1>;
    meshes::SurfaceMesh<dim> mesh;
    const bool has_outline = !keys.numbers("outline").empty();
    if (has_outline == !keys.text("surface").empty())
      throw InputError(keys.where(), "a moving wall needs either an outline or a surface");
    if (has_outline)
    {
      if constexpr (dim == 3)
        throw InputError(keys.at("outline"), "3D walls are surfaces: give `surface`");
      const auto v = keys.numbers("outline");
      if (v.size() < 4 || v.size() % 2)
        throw InputError(keys.at("outline"), "needs x, y pairs (at least two)");
      for (std::size_t i = 0; i + 1 < v.size(); i += 2)
      {
        Vector x = Vector::Zero();
        x[0] = v[i], x[1] = v[i + 1];
        mesh.vertices.push_back(x);
      }
      // A polygon given with its first point repeated at the end is closed: the last
      // segment ends at vertex 0, so the skin is closed (fluid that starts inside it is
      // removed, docs/bodies.md) rather than two loose ends that happen to meet.
      const bool closed =
          mesh.vertices.size() > 3 && (mesh.vertices.back() - mesh.vertices.front()).norm() <=
                                          1e-9 * (mesh.vertices[1] - mesh.vertices[0]).norm();
      if (closed)
        mesh.vertices.pop_back();
      const int n = int(mesh.vertices.size());
      for (int i = 0; i + 1 < n + (closed ? 1 : 0); ++i)
      {
        std::array<int, dim> f{};
        f[0] = i, f[1] = (i + 1) % n;
        mesh.faces.push_back(f);
      }
    }
    else
      mesh = meshes::read_surface_mesh<dim>(keys.file("surface"), keys.text("surface group"),
                                            keys.flag("flip normals"));
    const auto& p = context.placement;
    for (auto& x : mesh.vertices)
      x = p.position + p.rotation * x;
    coupling::PrescribedMotion<dim> motion;
    motion.velocity = p.velocity;
    motion.centre = p.position;
    motion.in_place = keys.flag("in place");
    const double speed = p.angular_velocity.norm();
    motion.angular_speed = dim == 2 ? p.angular_velocity[2] : speed;
    if (dim == 3 && speed > 0)
      motion.axis = p.angular_velocity / speed;
    return std::make_unique<coupling::PrescribedMotionBody<dim>>(mesh.vertices, mesh.faces, motion);
  }
};

const BodyKindRegistration registration(std::make_unique<MovingWallKind>());
} // namespace
} // namespace chipflex::apps
