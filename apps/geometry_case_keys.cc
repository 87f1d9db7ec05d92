// `subsection geometry` of a case file (apps/case_file.h): the fluid blocks, the domain,
// the tank and the extra walls (polylines, surface meshes, permeable barriers).

#include "apps/geometry_case_keys.h"

#include "apps/case_values.h"
#include "common/input_error.h"
#include "coupling/fluid_overlap.h"
#include "meshes/surface_mesh.h"

#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <filesystem>
#include <sstream>

namespace chipflex::apps
{
using dealii::ParameterHandler;
using dealii::Patterns::Anything;
using dealii::Patterns::Bool;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;

namespace
{
sph::WallModel wall_model_of(const std::string& key)
{
  return key == "lennard jones" ? sph::WallModel::lennard_jones
         : key == "thin skin"   ? sph::WallModel::thin_skin
                                : sph::WallModel::dummy_particles;
}

/// A surface given as 'FILE [group NAME] [flip]' (with `barrier` when `barrier` is not
/// null); relative names are looked up beside the case file.
template <int dim>
meshes::SurfaceMesh<dim> read_surface_spec(const std::string& key, const std::string& spec,
                                           const std::string& case_path, bool* barrier)
{
  std::istringstream words(spec);
  std::string file, word, group;
  bool flip = false;
  words >> file;
  while (words >> word)
    if (word == "flip")
      flip = true;
    else if (word == "barrier" && barrier)
      *barrier = true;
    else if (word == "group" && (words >> group))
      continue;
    else
      throw InputError(key, "'" + spec + "': expected 'FILE [group NAME] [flip]" +
                                (barrier ? std::string(" [barrier]'") : std::string("'")));
  namespace fs = std::filesystem;
  const fs::path beside = fs::path(case_path).parent_path() / file;
  if (!fs::path(file).is_absolute() && fs::exists(beside))
    file = beside.string();
  return meshes::read_surface_mesh<dim>(file, group, flip);
}

} // namespace

void declare_geometry_keys(ParameterHandler& prm)
{
  const sph::FluidParameters<2> fluid;
  const sph::TankDescription<2> tank;
  prm.enter_subsection("geometry");
  prm.declare_entry("fluid blocks", "0, 0, 1, 2", Anything(),
                    "Fluid boxes 'min corner, max corner' (2*dim numbers, m), separated by ';'.");
  prm.declare_entry("domain min", "", Anything(),
                    "The domain box, m: a fluid particle that leaves it is removed from the "
                    "run and counted (lost_particles in the log, probes and summary). Empty: "
                    "automatic (everything plus a quarter of its size on every side).");
  prm.declare_entry("domain max", "", Anything(), "See domain min, m.");
  prm.declare_entry("initial velocity", "", Anything(),
                    "Velocity of the fluid blocks at t = 0 (dim components), m/s; empty: at rest.");
  prm.declare_entry("fluid region", "", Anything(),
                    "'FILE [group NAME] [flip]': a closed surface (gmsh .msh or STL, m; normals "
                    "outwards, `flip` reverses them); fluid-block and buffer particles start "
                    "only inside it, at least dp/2 from its faces (a duct whose section is not "
                    "a box). Empty: the blocks as they are.");
  prm.declare_entry("lost fraction limit", default_text(fluid.maximum_lost_fraction), Double(0, 1),
                    "The run stops (its last checkpoint kept) once more than this fraction of "
                    "the fluid particles has left the domain box or turned non-finite, -.");
  prm.enter_subsection("tank");
  prm.declare_entry("enabled", tank.enabled ? "true" : "false", Bool(),
                    "A box tank around the fluid.");
  prm.declare_entry("min corner", "0, 0", Anything(), "Inner faces of the tank walls, m.");
  prm.declare_entry("max corner", "4, 3", Anything(), "Inner faces of the tank walls, m.");
  prm.declare_entry("open top", tank.open_top ? "true" : "false", Bool(), "No lid.");
  prm.declare_entry("open ends", "none", Selection("none|x|y|z"),
                    "Leave out the two walls normal to this axis: a channel (2D) or duct (3D, "
                    "with open top = false) whose fluid enters and leaves through open "
                    "boundaries. The walls must span the buffers.");
  prm.declare_entry("wall model", "dummy particles", Selection("dummy particles|lennard jones"),
                    "dummy particles (dynamic boundary condition) or lennard jones.");
  prm.declare_entry("dummy layers", std::to_string(tank.layers), Integer(0),
                    "Dummy particle layers; 0: enough to cover the kernel support (2h).");
  prm.declare_entry("lennard jones k", "0", Double(0),
                    "Wall force scale F(0) per unit mass, m/s^2; 0: 10 p_e / (rho0 dp), "
                    "p_e = rho0 (c0/10)^2.");
  prm.declare_entry("lennard jones R", "0", Double(0), "Cut-off distance, m; 0: dp.");
  prm.declare_entry("lennard jones r0", "0", Double(0), "Equilibrium distance, m; 0: dp/2.");
  prm.leave_subsection();
  prm.enter_subsection("walls");
  prm.declare_entry("polylines", "", Anything(),
                    "2D only: extra walls 'x1, y1, x2, y2, ...' (m), separated by ';'; the "
                    "fluid side is on the right of the direction of travel.");
  prm.declare_entry(
      "surfaces", "", Anything(),
      "Walls from surface meshes, separated by ';', each 'FILE [group NAME] "
      "[flip] [barrier]': a gmsh .msh (2D: its lines; 3D: its triangles and quads, or the "
      "boundary of its elements) or an STL file (3D), m. The fluid lies on the "
      "side of the face normals (`flip` reverses them); relative names are looked "
      "up beside the case file. `barrier`: a permeable barrier (bodies feel it, "
      "the fluid does not; subsection contact).");
  prm.declare_entry("wall model", "lennard jones",
                    Selection("dummy particles|lennard jones|thin skin"),
                    "Model of the extra walls. thin skin: a wall with fluid on both sides "
                    "(sided dummy particles; docs/sph.md, \"Thin skins\").");
  prm.declare_entry("fluid passes", "", Anything(),
                    "Numbers (1-based, comma-separated) of the polylines that are permeable "
                    "barriers: bodies feel them (subsection contact), the fluid does not.");
  prm.leave_subsection();
  prm.leave_subsection();
}

template <int dim>
void read_geometry_keys(ParameterHandler& prm, sph::CaseDescription<dim>& c,
                        const std::string& case_path)
{
  auto& f = c.fluid;
  prm.enter_subsection("geometry");
  for (const auto& block : split(prm.get("fluid blocks"), ';'))
  {
    const auto v = numbers("geometry/fluid blocks", block);
    if (v.size() != 2 * dim)
      throw InputError("geometry/fluid blocks",
                       "'" + block + "' needs " + std::to_string(2 * dim) + " numbers");
    sph::FluidBlock<dim> b;
    for (int d = 0; d < dim; ++d)
      b.min[d] = v[d], b.max[d] = v[dim + d];
    if (!((b.max - b.min).minCoeff() > 0))
      throw InputError("geometry/fluid blocks", "'" + block + "': max corner must exceed min");
    c.fluid_blocks.push_back(b);
  }
  const std::string dmin = prm.get("domain min"), dmax = prm.get("domain max");
  c.automatic_domain = trim(dmin).empty() && trim(dmax).empty();
  if (!c.automatic_domain)
  {
    f.domain_min = vector_of<dim>("geometry/domain min", dmin);
    f.domain_max = vector_of<dim>("geometry/domain max", dmax);
  }
  f.maximum_lost_fraction = prm.get_double("lost fraction limit");
  if (!trim(prm.get("initial velocity")).empty())
    c.initial_velocity = vector_of<dim>("geometry/initial velocity", prm.get("initial velocity"));
  if (!trim(prm.get("fluid region")).empty())
  {
    const auto mesh = read_surface_spec<dim>("geometry/fluid region", prm.get("fluid region"),
                                             case_path, nullptr);
    auto region = std::make_shared<coupling::SkinOverlap<dim>>(mesh.vertices, mesh.faces,
                                                               0.5 * c.fluid.particle_spacing);
    if (!region->closed())
      throw InputError("geometry/fluid region", "the surface is not closed");
    c.fluid_region = [region](const Eigen::Matrix<double, dim, 1>& x)
    { return region->encloses(x) && !region->near_face(x); };
  }
  prm.enter_subsection("tank");
  c.tank.enabled = prm.get_bool("enabled");
  c.tank.min = vector_of<dim>("geometry/tank/min corner", prm.get("min corner"));
  c.tank.max = vector_of<dim>("geometry/tank/max corner", prm.get("max corner"));
  if (c.tank.enabled && !((c.tank.max - c.tank.min).minCoeff() > 0))
    throw InputError("geometry/tank/max corner", "must lie above the min corner");
  c.tank.open_top = prm.get_bool("open top");
  {
    const std::string ends = prm.get("open ends");
    c.tank.open_axis = ends == "none" ? -1 : ends[0] - 'x';
    if (c.tank.open_axis >= dim)
      throw InputError("geometry/tank/open ends", "'" + ends + "' in a 2D case");
  }
  c.tank.model = wall_model_of(prm.get("wall model"));
  c.tank.layers = prm.get_integer("dummy layers");
  c.tank.lennard_jones = {prm.get_double("lennard jones k"), prm.get_double("lennard jones R"),
                          prm.get_double("lennard jones r0")};
  prm.leave_subsection();
  prm.enter_subsection("walls");
  const auto lines = split(prm.get("polylines"), ';');
  if (!lines.empty() && dim != 2)
    throw InputError("geometry/walls/polylines", "extra polyline walls are 2D only");
  for (std::size_t k = 0; k < lines.size(); ++k)
  {
    const auto v = numbers("geometry/walls/polylines", lines[k]);
    if (v.size() < 4 || v.size() % 2)
      throw InputError("geometry/walls/polylines", "'" + lines[k] + "' needs x, y pairs (>= 2)");
    sph::WallSurface<dim> w;
    w.name = "wall " + std::to_string(k + 1);
    w.model = wall_model_of(prm.get("wall model"));
    for (std::size_t i = 0; i + 1 < v.size(); i += 2)
    {
      Eigen::Matrix<double, dim, 1> x = Eigen::Matrix<double, dim, 1>::Zero();
      x[0] = v[i], x[1] = v[i + 1];
      w.vertices.push_back(x);
    }
    for (int i = 0; i + 1 < int(w.vertices.size()); ++i)
    {
      std::array<int, dim> face{};
      face[0] = i, face[1] = i + 1;
      w.faces.push_back(face);
    }
    c.walls.push_back(w);
  }
  for (double k : numbers("geometry/walls/fluid passes", prm.get("fluid passes")))
  {
    if (k != std::floor(k) || k < 1 || k > double(c.walls.size()))
    {
      std::ostringstream what;
      what << "no polyline " << k << " (there are " << c.walls.size() << ")";
      throw InputError("geometry/walls/fluid passes", what.str());
    }
    c.walls[std::size_t(k) - 1].fluid_passes = true;
  }
  const auto surfaces = split(prm.get("surfaces"), ';');
  for (std::size_t k = 0; k < surfaces.size(); ++k)
  {
    bool barrier = false;
    const auto mesh =
        read_surface_spec<dim>("geometry/walls/surfaces", surfaces[k], case_path, &barrier);
    sph::WallSurface<dim> w;
    w.name = "surface " + std::to_string(k + 1);
    w.model = wall_model_of(prm.get("wall model"));
    w.vertices = mesh.vertices;
    w.faces = mesh.faces;
    w.fluid_passes = barrier;
    c.walls.push_back(w);
  }
  prm.leave_subsection();
  prm.leave_subsection();
}

template void read_geometry_keys(ParameterHandler&, sph::CaseDescription<2>&, const std::string&);
template void read_geometry_keys(ParameterHandler&, sph::CaseDescription<3>&, const std::string&);
} // namespace chipflex::apps
