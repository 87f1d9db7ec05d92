#pragma once
// Particle frames for ParaView: DIR/particles/frame_NNNNNN.h5 (position and velocity as
// n x 3, pressure, density, kind 0 boundary / 1 fluid, the stable id, and the vertex
// cells 0..n-1) and DIR/particles.xdmf, a temporal collection of Polyvertex grids over
// those files, rewritten atomically after every frame so that ParaView can open it while
// the run goes on. Every frame carries its own particle count (particles may be removed
// during a run); (kind, id) names one particle in every frame. docs/output.md lists the
// arrays and units.

#include <cstdint>
#include <string>
#include <vector>

namespace chipflex::sph
{
template <int dim>
class FluidSolver;
}

namespace chipflex::apps
{
struct ParticleFrame
{
  std::size_t n = 0;
  std::vector<double> position, velocity; ///< n x 3 (z = 0 in 2D)
  std::vector<double> pressure, density;
  std::vector<std::int64_t> kind; ///< 0 boundary, 1 fluid
  /// Stable within its kind: fluid 0..n_fluid-1 in order of creation, boundary by wall
  /// attachment (sph::ParticleArrays::id); the array order changes between frames.
  std::vector<std::int64_t> id;
};

template <int dim>
ParticleFrame particle_frame(const sph::FluidSolver<dim>& fluid);

class ParticleOutput
{
public:
  explicit ParticleOutput(const std::string& directory);
  /// Restart: keep the frames written up to `time` (their times are read back from
  /// the frame files), so numbering and the XDMF continue.
  void resume(double time);
  void write(double time, const ParticleFrame& frame);
  std::size_t n_frames() const { return frames_.size(); }
  /// Time of the last frame written (or kept by resume()); -infinity if none.
  double last_time() const;

private:
  void write_xdmf() const;
  struct Frame
  {
    double time;
    std::size_t n;
    std::string file;
  };
  std::string directory_;
  std::vector<Frame> frames_;
};
} // namespace chipflex::apps
