#pragma once
// Particle frames for ParaView: DIR/particles/frame_NNNNNN.h5 (position and velocity as
// n x 3, pressure, density, kind 0 boundary / 1 fluid, the per-kind id, the global id,
// the body (wall) a boundary particle belongs to, and the vertex cells 0..n-1) and
// DIR/particles.xdmf, a temporal collection of Polyvertex grids over those files,
// rewritten atomically after every frame so that ParaView can open it while the run goes
// on. Every frame carries its own particle count (particles may be removed during a
// run); the global id names one particle in every frame and is the XDMF's GlobalId
// attribute, which ParaView's readers make the point data's global ids. docs/output.md
// lists the arrays and units. Under mpirun every rank holds its own part of a frame and
// the ranks write the frame file together through parallel HDF5
// (common/distributed_hdf5_file.h); rank 0 adds the attributes and the XDMF.

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
  /// Particles in this frame; under MPI (`distributed`) this rank's part of the frame:
  /// on rank 0 the wall particles and its own fluid, on the others their own fluid.
  std::size_t n = 0;
  bool distributed = false;
  std::vector<double> position, velocity; ///< n x 3 (z = 0 in 2D)
  std::vector<double> pressure, density;
  std::vector<std::int64_t> kind; ///< 0 boundary, 1 fluid
  /// Stable within its kind: fluid 0..n_fluid-1 in order of creation, boundary by wall
  /// attachment (sph::ParticleArrays::id); the array order changes between frames.
  std::vector<std::int64_t> id;
  /// Unique over both kinds, the same particle's in every frame (FluidSolver::global_id).
  std::vector<std::int64_t> global_id;
  /// The wall or body a boundary particle belongs to, an index into body_names; -1 for
  /// a fluid particle (as DualSPHysics' mk tells the boundaries apart).
  std::vector<std::int64_t> body;
  /// Every wall and body of the fluid in the solver's order (tank first when it has one),
  /// named as in walls.xdmf and skins.xdmf.
  std::vector<std::string> body_names;
};

template <int dim>
ParticleFrame particle_frame(const sph::FluidSolver<dim>& fluid);

class ParticleOutput
{
public:
  /// `writes` false (MPI ranks other than 0): keeps the frame list and writes only its
  /// part of distributed frames.
  explicit ParticleOutput(const std::string& directory, bool writes = true);
  /// Restart: keep the frames written up to `time` (their times are read back from
  /// the frame files), so numbering and the XDMF continue.
  void resume(double time);
  void write(double time, const ParticleFrame& frame);
  std::size_t n_frames() const { return frames_.size(); }
  /// Time of the last frame written (or kept by resume()); -infinity if none.
  double last_time() const;

private:
  void write_xdmf() const;
  /// Every rank its part of `f` into the frame file `name` (collective); returns the
  /// particles of all ranks.
  std::size_t write_distributed(const std::string& name, double time, const ParticleFrame& f);
  struct Frame
  {
    double time;
    std::size_t n;
    std::string file;
    /// Has global_id and body (frames of older runs kept by a restart have not).
    bool with_global_ids;
  };
  std::string directory_;
  bool writes_;
  std::vector<Frame> frames_;
  std::vector<std::string> body_names_; ///< of the last frame, for the XDMF's legend
};
} // namespace chipflex::apps
