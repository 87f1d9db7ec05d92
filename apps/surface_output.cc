#include "apps/surface_output.h"

#include "apps/array_names.h"
#include "common/atomic_output.h"
#include "common/hdf5_file.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace chipflex::apps
{
namespace
{
template <int dim, typename V>
std::vector<double> as_xyz(const std::vector<V>& v)
{
  std::vector<double> out(3 * v.size(), 0.0);
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int d = 0; d < dim; ++d)
      out[3 * i + d] = v[i][d];
  return out;
}

std::string data_item(const std::string& dims, const char* type, const std::string& path)
{
  return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + type +
         "\" Precision=\"8\" Format=\"HDF\">" + path + "</DataItem>";
}
} // namespace

std::string surface_name(const std::string& name)
{
  std::string s = name.empty() ? "surface" : name;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
      c = '_';
  return s;
}

template <int dim>
SurfaceOutput<dim>::SurfaceOutput(const std::string& directory, const std::string& series)
    : directory_(directory), series_(series)
{
}

template <int dim>
std::string SurfaceOutput<dim>::frame_name(std::size_t k) const
{
  char name[64];
  std::snprintf(name, sizeof name, "/frame_%06zu.h5", k);
  return series_ + name;
}

template <int dim>
double SurfaceOutput<dim>::last_time() const
{
  return frames_.empty() ? -std::numeric_limits<double>::infinity() : frames_.back().time;
}

template <int dim>
void SurfaceOutput<dim>::resume(double time)
{
  frames_.clear();
  for (std::size_t k = 0;; ++k)
  {
    const std::string name = frame_name(k);
    const std::string path = directory_ + "/" + name;
    if (!std::filesystem::exists(path))
      break;
    Hdf5File h5(path, Hdf5File::Mode::read);
    const double t = h5.read_double_attribute("/", "time");
    if (t > time * (1 + 1e-12) + 1e-15)
      break;
    Frame f{t, name, {}};
    for (const auto& surface : h5.read_strings("/names"))
    {
      const std::string group = "/" + surface;
      Entry e{surface, 0, 0, h5.read_strings(group + "/arrays"), h5.read_strings(group + "/units")};
      std::vector<std::size_t> shape;
      h5.read_doubles(group + "/vertices", &shape);
      e.n_vertices = shape.at(0);
      h5.read_integers(group + "/faces", &shape);
      e.n_faces = shape.at(0);
      f.surfaces.push_back(std::move(e));
    }
    frames_.push_back(std::move(f));
  }
}

template <int dim>
void SurfaceOutput<dim>::write(double time, const std::vector<Surface>& surfaces)
{
  Frame f{time, frame_name(frames_.size()), {}};
  std::filesystem::create_directories(directory_ + "/" + series_);
  {
    AtomicOutput out(directory_ + "/" + f.file);
    {
      Hdf5File h5(out.temporary_path(), Hdf5File::Mode::create);
      h5.write_attribute("/", "time", time);
      std::vector<std::string> names;
      for (const auto& s : surfaces)
      {
        // Unique within the frame (and, surfaces coming in the same order, across frames).
        std::string name = surface_name(s.name);
        for (int k = 2; std::find(names.begin(), names.end(), name) != names.end(); ++k)
          name = surface_name(s.name) + "_" + std::to_string(k);
        Entry e{name, s.vertices.size(), s.faces.size(), {}, {}};
        const std::string group = "/" + e.name;
        std::vector<std::int64_t> faces;
        for (const auto& face : s.faces)
          faces.insert(faces.end(), face.begin(), face.end());
        h5.ensure_group(group);
        h5.write(group + "/vertices", as_xyz<dim>(s.vertices), {e.n_vertices, 3});
        h5.write(group + "/faces", faces, {e.n_faces, std::size_t(dim)});
        for (const auto& a : s.arrays)
        {
          if (a.values.size() != e.n_vertices)
            throw std::logic_error("SurfaceOutput: array '" + a.name + "' of '" + s.name +
                                   "' has " + std::to_string(a.values.size()) + " values for " +
                                   std::to_string(e.n_vertices) + " vertices");
          h5.write(group + "/" + a.name, as_xyz<dim>(a.values), {e.n_vertices, 3});
          h5.write_attribute(group + "/" + a.name, "unit", a.unit);
          e.arrays.push_back(a.name);
          e.units.push_back(a.unit);
        }
        h5.write(group + "/arrays", e.arrays);
        h5.write(group + "/units", e.units);
        names.push_back(e.name);
        f.surfaces.push_back(std::move(e));
      }
      h5.write("/names", names);
    }
    out.commit();
  }
  frames_.push_back(std::move(f));
  write_xdmf();
}

template <int dim>
void SurfaceOutput<dim>::write_xdmf() const
{
  // One temporal collection per surface, its frames all named after it. Of the layouts
  // ParaView 5.11 reads, this is the one whose blocks keep their names and order in
  // every frame: a temporal collection of spatial collections makes the legacy reader
  // and Xdmf3ReaderT rename each frame's blocks (gate, gate[1], ...).
  std::vector<std::string> names;
  for (const auto& f : frames_)
    for (const auto& s : f.surfaces)
      if (std::find(names.begin(), names.end(), s.name) == names.end())
        names.push_back(s.name);

  AtomicOutput out(directory_ + "/" + series_ + ".xdmf");
  {
    std::ofstream x(out.temporary_path());
    x.precision(17);
    x << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
         "<Xdmf Version=\"2.0\">\n <Domain>\n";
    for (const auto& name : names)
    {
      x << "  <Grid Name=\"" << name << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
      for (const auto& f : frames_)
        for (const auto& s : f.surfaces)
        {
          if (s.name != name)
            continue;
          const std::string n = std::to_string(s.n_vertices);
          const std::string base = f.file + ":/" + s.name + "/";
          x << "   <Grid Name=\"" << s.name << "\" GridType=\"Uniform\">\n"
            << "    <Time Value=\"" << f.time << "\"/>\n"
            << "    <Topology TopologyType=\"" << (dim == 2 ? "Polyline" : "Triangle")
            << "\" NumberOfElements=\"" << s.n_faces << "\" NodesPerElement=\"" << dim << "\">"
            << data_item(std::to_string(s.n_faces) + " " + std::to_string(dim), "Int",
                         base + "faces")
            << "</Topology>\n"
            << "    <Geometry GeometryType=\"XYZ\">"
            << data_item(n + " 3", "Float", base + "vertices") << "</Geometry>\n";
          for (std::size_t a = 0; a < s.arrays.size(); ++a)
            x << "    <Attribute Name=\"" << name_with_unit(s.arrays[a], s.units[a])
              << "\" AttributeType=\"Vector\" Center=\"Node\">"
              << "<Information Name=\"unit\" Value=\"" << s.units[a] << "\"/>"
              << data_item(n + " 3", "Float", base + s.arrays[a]) << "</Attribute>\n";
          x << "   </Grid>\n";
        }
      x << "  </Grid>\n";
    }
    x << " </Domain>\n</Xdmf>\n";
    if (!x)
      throw std::runtime_error("cannot write " + out.temporary_path());
  }
  out.commit();
}

template class SurfaceOutput<2>;
template class SurfaceOutput<3>;
} // namespace chipflex::apps
