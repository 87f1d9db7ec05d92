#include "apps/particle_output.h"

#include "apps/array_names.h"
#include "apps/surface_output.h"
#include "common/atomic_output.h"
#include "common/distributed_hdf5_file.h"
#include "common/hdf5_file.h"
#include "sph/fluid_solver.h"
#include "sph/particle_exchange.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace chipflex::apps
{
template <int dim>
ParticleFrame particle_frame(const sph::FluidSolver<dim>& fluid)
{
  // Over MPI this rank's part: rank 0 the walls and its own fluid, the others their own.
  sph::ParticleArrays<dim> own;
  if (const auto* exchange = fluid.exchange())
    own = exchange->own_rows(fluid.particles());
  const auto& p = fluid.exchange() ? own : fluid.particles();
  const std::size_t n_walls = fluid.particles().n_boundary;
  ParticleFrame f;
  f.n = p.size();
  f.distributed = fluid.exchange() != nullptr;
  f.position.assign(3 * f.n, 0.0);
  f.velocity.assign(3 * f.n, 0.0);
  f.pressure.resize(f.n);
  f.density.resize(f.n);
  f.kind.resize(f.n);
  f.id.resize(f.n);
  f.global_id.resize(f.n);
  f.body.resize(f.n);
  for (int w = 0; w < fluid.n_walls(); ++w)
    f.body_names.push_back(surface_name(fluid.wall(w).name));
  for (std::size_t i = 0; i < f.n; ++i)
  {
    for (int d = 0; d < dim; ++d)
    {
      f.position[3 * i + d] = p.position[d][i];
      f.velocity[3 * i + d] = p.velocity[d][i];
    }
    const bool wall = i < p.n_boundary;
    f.pressure[i] = fluid.pressure_at_density(p.density[i]);
    f.density[i] = p.density[i];
    f.kind[i] = std::int64_t(wall ? sph::ParticleKind::boundary : sph::ParticleKind::fluid);
    f.id[i] = std::int64_t(p.id[i]);
    // FluidSolver::global_id, for these arrays (the wall block is the solver's own).
    f.global_id[i] = std::int64_t(wall ? p.id[i] : n_walls + p.id[i]);
    f.body[i] = wall ? fluid.wall_of(i) : -1;
  }
  return f;
}

namespace
{
/// The frame's per-particle datasets in file order, with their columns: one list for the
/// one-process and the distributed writers.
template <class Write>
void for_each_array(const ParticleFrame& f, Write&& write)
{
  write("/position", f.position, 3);
  write("/velocity", f.velocity, 3);
  write("/pressure", f.pressure, 1);
  write("/density", f.density, 1);
  write("/kind", f.kind, 1);
  write("/id", f.id, 1);
  write("/global_id", f.global_id, 1);
  write("/body", f.body, 1);
}
} // namespace

template ParticleFrame particle_frame(const sph::FluidSolver<2>&);
template ParticleFrame particle_frame(const sph::FluidSolver<3>&);

ParticleOutput::ParticleOutput(const std::string& directory, bool writes)
    : directory_(directory), writes_(writes)
{
  if (writes_)
    std::filesystem::create_directories(directory_ + "/particles");
}

double ParticleOutput::last_time() const
{
  return frames_.empty() ? -std::numeric_limits<double>::infinity() : frames_.back().time;
}

void ParticleOutput::resume(double time)
{
  frames_.clear();
  for (std::size_t k = 0;; ++k)
  {
    char name[64];
    std::snprintf(name, sizeof name, "particles/frame_%06zu.h5", k);
    const std::string path = directory_ + "/" + name;
    if (!std::filesystem::exists(path))
      break;
    Hdf5File h5(path, Hdf5File::Mode::read);
    const double t = h5.read_double_attribute("/", "time");
    if (t > time * (1 + 1e-12) + 1e-15)
      break;
    const bool with_global_ids = h5.exists("/global_id");
    if (with_global_ids)
      body_names_ = h5.read_strings("/body_names");
    frames_.push_back(
        {t, std::size_t(h5.read_integer_attribute("/", "n_particles")), name, with_global_ids});
  }
}

void ParticleOutput::write(double time, const ParticleFrame& f)
{
  char name[64];
  std::snprintf(name, sizeof name, "particles/frame_%06zu.h5", frames_.size());
  if (f.distributed)
  {
    const std::size_t n = write_distributed(name, time, f);
    frames_.push_back({time, n, name, true});
    if (writes_)
    {
      body_names_ = f.body_names;
      write_xdmf();
    }
    return;
  }
  if (!writes_)
  {
    frames_.push_back({time, f.n, name, true});
    return;
  }
  {
    AtomicOutput out(directory_ + "/" + name);
    {
      Hdf5File h5(out.temporary_path(), Hdf5File::Mode::create);
      h5.write_attribute("/", "time", time);
      h5.write_attribute("/", "n_particles", std::int64_t(f.n));
      for_each_array(
          f,
          [&](const char* set, const auto& data, std::size_t columns) {
            h5.write(set, data, columns > 1 ? std::vector{f.n, columns} : std::vector{f.n});
          });
      h5.write("/body_names", f.body_names);
      // One vertex cell per particle: ParaView's Xdmf3 readers build no cells from a
      // Polyvertex topology without connectivity (the legacy reader does).
      std::vector<std::int64_t> cells(f.n);
      for (std::size_t i = 0; i < f.n; ++i)
        cells[i] = std::int64_t(i);
      h5.write("/cells", cells, {f.n});
    }
    out.commit();
  }
  frames_.push_back({time, f.n, name, true});
  body_names_ = f.body_names;
  write_xdmf();
}

std::size_t ParticleOutput::write_distributed(const std::string& name, double time,
                                              const ParticleFrame& f)
{
  // Written beside the final path and renamed when complete, as AtomicOutput does (its
  // temporary name holds the process id, which differs between the ranks).
  const std::string path = directory_ + "/" + name, temporary = path + ".tmp-ranks";
  std::size_t n = 0;
  {
    DistributedHdf5File h5(temporary, f.n);
    n = h5.rows();
    for_each_array(f, [&](const char* set, const auto& data, std::size_t columns)
                   { h5.write_rows(set, data, columns); });
    std::vector<std::int64_t> cells(f.n);
    for (std::size_t i = 0; i < f.n; ++i)
      cells[i] = std::int64_t(h5.first_row() + i);
    h5.write_rows("/cells", cells, 1);
  } // the collective close: every rank's rows are in the file
  if (!writes_)
    return n;
  {
    Hdf5File h5(temporary, Hdf5File::Mode::update);
    h5.write_attribute("/", "time", time);
    h5.write_attribute("/", "n_particles", std::int64_t(n));
    h5.write("/body_names", f.body_names);
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error)
  {
    std::filesystem::remove(temporary, error);
    throw std::runtime_error("cannot rename " + temporary + " to " + path);
  }
  return n;
}

void ParticleOutput::write_xdmf() const
{
  // What the body numbers mean, in the body array's Information (ParaView's legend is
  // the number; the names are in every frame's /body_names too).
  std::string bodies = "-1 fluid";
  for (std::size_t b = 0; b < body_names_.size(); ++b)
    bodies += ", " + std::to_string(b) + " " + body_names_[b];

  AtomicOutput out(directory_ + "/particles.xdmf");
  {
    std::ofstream x(out.temporary_path());
    x.precision(17);
    x << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
         "<Xdmf Version=\"2.0\">\n <Domain>\n"
         "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& f : frames_)
    {
      auto item = [&](const std::string& set, int components, const char* type)
      {
        std::string dims = std::to_string(f.n) + (components > 1 ? " 3" : "");
        return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + type +
               "\" Precision=\"8\" Format=\"HDF\">" + f.file + ":/" + set + "</DataItem>";
      };
      // ParaView shows the array as name_unit (apps/array_names.h); the dataset keeps
      // the bare name. `type`: Scalar, Vector or GlobalId.
      auto attribute = [&](const std::string& set, const std::string& unit, const char* type,
                           const char* number, const std::string& meaning = "",
                           const std::string& shown = "")
      {
        const int components = std::string(type) == "Vector" ? 3 : 1;
        x << "    <Attribute Name=\"" << (shown.empty() ? name_with_unit(set, unit) : shown)
          << "\" AttributeType=\"" << type << "\" Center=\"Node\">"
          << "<Information Name=\"unit\" Value=\"" << unit << "\"/>";
        if (!meaning.empty())
          x << "<Information Name=\"meaning\" Value=\"" << meaning << "\"/>";
        x << item(set, components, number) << "</Attribute>\n";
      };
      // The same Name in every frame: ParaView names the block after it.
      x << "   <Grid Name=\"particles\" GridType=\"Uniform\">\n"
        << "    <Time Value=\"" << f.time << "\"/>\n"
        << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << f.n
        << "\" NodesPerElement=\"1\">" << item("cells", 1, "Int") << "</Topology>\n"
        << "    <Geometry GeometryType=\"XYZ\">" << item("position", 3, "Float") << "</Geometry>\n";
      attribute("velocity", "m/s", "Vector", "Float");
      attribute("pressure", "Pa", "Scalar", "Float");
      attribute("density", "kg/m^3", "Scalar", "Float");
      attribute("kind", "-", "Scalar", "Int", "0 boundary, 1 fluid");
      attribute("id", "-", "Scalar", "Int", "stable per kind");
      if (f.with_global_ids)
      {
        // AttributeType GlobalId: the legacy XDMF reader and both Xdmf3 readers make it
        // the point data's global ids (what Find Data and selections by id go by).
        attribute("global_id", "-", "GlobalId", "Int", "unique, the same particle in every frame",
                  "GlobalIds");
        attribute("body", "-", "Scalar", "Int", bodies);
      }
      x << "   </Grid>\n";
    }
    x << "  </Grid>\n </Domain>\n</Xdmf>\n";
    if (!x)
      throw std::runtime_error("cannot write " + out.temporary_path());
  }
  out.commit();
}
} // namespace chipflex::apps
