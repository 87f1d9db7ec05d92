#pragma once
// What the coupling layer needs of any body (rigid, rigid chain, reduced flexible):
// its skin (surface nodes and faces) in world coordinates, and a way to receive forces
// on those nodes. Bodies implement this; coupling/ never needs to know the body kind.

#include <Eigen/Core>
#include <array>
#include <vector>

namespace chipflex::mbs
{
template <int dim>
class SkinBody
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  virtual ~SkinBody() = default;

  virtual std::size_t n_skin_nodes() const = 0;
  /// Skin faces as skin-node indices (0 .. n_skin_nodes-1); 2D segments / 3D triangles,
  /// oriented with the outward normal as in sph::WallSurface.
  virtual const std::vector<std::array<int, dim>>& skin_faces() const = 0;
  /// World positions and velocities of the skin nodes in the current state.
  virtual void skin_positions(std::vector<Vector>& x) const = 0;
  virtual void skin_velocities(std::vector<Vector>& v) const = 0;
  /// True for a skin that keeps its place while its velocity says it moves: a surface
  /// that moves along itself (a turning borehole wall). Its velocity is a sliding one,
  /// tangential to the surface.
  virtual bool skin_slides_in_place() const { return false; }
  /// External forces on the skin nodes (world frame, N; 2D: N per metre of depth),
  /// held constant until replaced. The body maps them to its generalised forces
  /// (resultant, moment, Psi_skin^T f for the modes).
  virtual void set_skin_forces(const std::vector<Vector>& f) = 0;
};
} // namespace chipflex::mbs
