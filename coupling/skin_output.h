#pragma once
// The deformed skins of the coupled bodies for ParaView, beside the particles:
// DIR/skins/frame_NNNNNN.h5 (per body: vertex positions n x 3, faces, the fluid force
// on every skin node n x 3) and DIR/skins.xdmf, a temporal collection with one
// Polyline (2D) or Triangle (3D) grid per body, rewritten atomically after every frame
// so ParaView shows the gate bending while the run goes on. Same layout and restart
// rule as the particle frames (apps/particle_output.h).

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace chipflex::coupling
{
template <int dim>
class SkinOutput
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  struct Skin
  {
    std::string name;
    std::vector<Vector> vertices, forces;
    std::vector<std::array<int, dim>> faces;
  };

  explicit SkinOutput(const std::string& directory);
  /// Restart: keep the frames written up to `time`.
  void resume(double time);
  void write(double time, const std::vector<Skin>& skins);
  std::size_t n_frames() const { return frames_.size(); }

private:
  void write_xdmf() const;
  struct Frame
  {
    double time;
    std::string file;
    std::vector<std::string> names;
    std::vector<std::size_t> n_vertices, n_faces;
  };
  std::string directory_;
  std::vector<Frame> frames_;
};
} // namespace chipflex::coupling
