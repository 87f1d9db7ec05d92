#pragma once
// A time series of named surface meshes for ParaView: the body skins (DIR/skins.xdmf)
// and the rigid walls (DIR/walls.xdmf). Every frame is one HDF5 file,
// DIR/<series>/frame_NNNNNN.h5, holding per surface its vertices (n x 3, z = 0 in 2D),
// its faces (segments in 2D, triangles in 3D) and its point arrays (n x 3 vectors).
// The XDMF, rewritten atomically after every frame so ParaView can open it while the
// run goes on, holds one temporal collection per surface, named after it, so ParaView
// shows one block per surface with the same name and place in every frame.
// Same restart rule as the particle frames (apps/particle_output.h). docs/output.md
// lists the files, arrays and units.

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace chipflex::apps
{
template <int dim>
class SurfaceOutput
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  struct PointArray
  {
    std::string name; ///< no spaces (ParaView, Python scripts)
    std::string unit; ///< SI, written into the XDMF as Information "unit" and into the
                      ///< name ParaView shows (apps/array_names.h)
    std::vector<Vector> values;
  };
  struct Surface
  {
    std::string name;
    std::vector<Vector> vertices;
    std::vector<std::array<int, dim>> faces;
    std::vector<PointArray> arrays;
  };

  /// `series`: "skins" or "walls", the XDMF's and the frame folder's name.
  SurfaceOutput(const std::string& directory, const std::string& series);
  /// Restart: keep the frames written up to `time`.
  void resume(double time);
  void write(double time, const std::vector<Surface>& surfaces);
  std::size_t n_frames() const { return frames_.size(); }
  /// Time of the last frame written (or kept by resume()); -infinity if none.
  double last_time() const;

private:
  void write_xdmf() const;
  struct Entry
  {
    std::string name;
    std::size_t n_vertices, n_faces;
    std::vector<std::string> arrays, units;
  };
  struct Frame
  {
    double time;
    std::string file;
    std::vector<Entry> surfaces;
  };
  std::string frame_name(std::size_t k) const;

  std::string directory_, series_;
  std::vector<Frame> frames_;
};

/// `name` made safe as an HDF5 group and a ParaView block name: letters, digits and '_'
/// only ("wall 1" -> "wall_1").
std::string surface_name(const std::string& name);
} // namespace chipflex::apps
