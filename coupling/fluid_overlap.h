#pragma once
// Fluid filled by blocks on a lattice ignores the bodies placed in it: particles that
// start inside a body, or on its skin, would be shot out by the wall force in the first
// steps. Before the first step they are removed (as DualSPHysics' GenCase fills only the
// void): those closer than `margin` to a skin face, and, for a closed skin, those inside
// it (generalised winding number: the solid angle the skin subtends, over 4 pi in 3D,
// the angle over 2 pi in 2D, is 1 inside an outward closed surface and 0 outside).

#include <Eigen/Core>
#include <array>
#include <vector>

namespace chipflex::coupling
{
template <int dim>
class SkinOverlap
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  SkinOverlap(std::vector<Vector> nodes, std::vector<std::array<int, dim>> faces, double margin);
  /// True if `x` lies inside the closed skin or within `margin` of a face.
  bool operator()(const Vector& x) const;
  /// True if `x` lies within `margin` of a face.
  bool near_face(const Vector& x) const;
  /// True if the skin is closed and `x` lies inside it (winding number above 1/2).
  bool encloses(const Vector& x) const;
  bool closed() const { return closed_; }

private:
  std::vector<Vector> nodes_;
  std::vector<std::array<int, dim>> faces_;
  double margin_;
  bool closed_;
  Vector lower_, upper_; ///< bounding box of the skin, widened by the margin
};
} // namespace chipflex::coupling
