#include "coupling/skin_output.h"

#include "common/atomic_output.h"
#include "common/hdf5_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace chipflex::coupling
{
namespace
{
std::string frame_name(std::size_t k)
{
  char name[64];
  std::snprintf(name, sizeof name, "skins/frame_%06zu.h5", k);
  return name;
}

template <int dim, typename V>
std::vector<double> as_xyz(const std::vector<V>& v)
{
  std::vector<double> out(3 * v.size(), 0.0);
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int d = 0; d < dim; ++d)
      out[3 * i + d] = v[i][d];
  return out;
}
} // namespace

template <int dim>
SkinOutput<dim>::SkinOutput(const std::string& directory) : directory_(directory)
{
  std::filesystem::create_directories(directory_ + "/skins");
}

template <int dim>
void SkinOutput<dim>::resume(double time)
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
    Frame f{t, name, h5.read_strings("/names"), {}, {}};
    for (const auto& body : f.names)
    {
      std::vector<std::size_t> shape;
      h5.read_doubles("/" + body + "/vertices", &shape);
      f.n_vertices.push_back(shape.at(0));
      h5.read_integers("/" + body + "/faces", &shape);
      f.n_faces.push_back(shape.at(0));
    }
    frames_.push_back(std::move(f));
  }
}

template <int dim>
void SkinOutput<dim>::write(double time, const std::vector<Skin>& skins)
{
  Frame f{time, frame_name(frames_.size()), {}, {}, {}};
  {
    AtomicOutput out(directory_ + "/" + f.file);
    {
      Hdf5File h5(out.temporary_path(), Hdf5File::Mode::create);
      h5.write_attribute("/", "time", time);
      for (const auto& s : skins)
      {
        std::vector<std::int64_t> faces;
        for (const auto& face : s.faces)
          faces.insert(faces.end(), face.begin(), face.end());
        h5.ensure_group("/" + s.name);
        h5.write("/" + s.name + "/vertices", as_xyz<dim>(s.vertices), {s.vertices.size(), 3});
        h5.write("/" + s.name + "/force", as_xyz<dim>(s.forces), {s.forces.size(), 3});
        h5.write("/" + s.name + "/faces", faces, {s.faces.size(), std::size_t(dim)});
        f.names.push_back(s.name);
        f.n_vertices.push_back(s.vertices.size());
        f.n_faces.push_back(s.faces.size());
      }
      h5.write("/names", f.names);
    }
    out.commit();
  }
  frames_.push_back(std::move(f));
  write_xdmf();
}

template <int dim>
void SkinOutput<dim>::write_xdmf() const
{
  AtomicOutput out(directory_ + "/skins.xdmf");
  {
    std::ofstream x(out.temporary_path());
    x.precision(17);
    x << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
         "<Xdmf Version=\"2.0\">\n <Domain>\n"
         "  <Grid Name=\"skins\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& f : frames_)
    {
      x << "   <Grid Name=\"bodies\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
        << "    <Time Value=\"" << f.time << "\"/>\n";
      for (std::size_t b = 0; b < f.names.size(); ++b)
      {
        const std::string n = std::to_string(f.n_vertices[b]);
        const std::string base = f.file + ":/" + f.names[b];
        x << "    <Grid Name=\"" << f.names[b] << "\" GridType=\"Uniform\">\n"
          << "     <Topology TopologyType=\"" << (dim == 2 ? "Polyline" : "Triangle")
          << "\" NumberOfElements=\"" << f.n_faces[b] << "\" NodesPerElement=\"" << dim
          << "\"><DataItem Dimensions=\"" << f.n_faces[b] << " " << dim
          << "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" << base
          << "/faces</DataItem></Topology>\n"
          << "     <Geometry GeometryType=\"XYZ\"><DataItem Dimensions=\"" << n
          << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << base
          << "/vertices</DataItem></Geometry>\n"
          << "     <Attribute Name=\"fluid force\" AttributeType=\"Vector\" Center=\"Node\">"
          << "<DataItem Dimensions=\"" << n
          << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << base
          << "/force</DataItem></Attribute>\n    </Grid>\n";
      }
      x << "   </Grid>\n";
    }
    x << "  </Grid>\n </Domain>\n</Xdmf>\n";
    if (!x)
      throw std::runtime_error("cannot write " + out.temporary_path());
  }
  out.commit();
}

template class SkinOutput<2>;
template class SkinOutput<3>;
} // namespace chipflex::coupling
