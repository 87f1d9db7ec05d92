#pragma once
// The skin of a clamped reduced beam (the elastic gate) with large-rotation
// kinematics. A linear floating-frame body keeps its nodes on x = xbar + Psi q, so a
// cantilever bent by a 1 rad tip rotation still has its tip at its original height
// (no foreshortening: the measured dy of the Antoci gate, 17 mm, is a second-order
// effect the linear body cannot show) and grows longer.
//
// Here the linear field supplies only the cross-section rotation along the axis,
//   theta(s) = (u_a(s, -t/2) - u_a(s, +t/2)) / t        (u_a: axial displacement),
// and the skin is rebuilt inextensibly from it (an Euler-Bernoulli "rotation field"
// reconstruction, as co-rotational beam formulations do):
//   X(s) = X(0) + int_0^s (a cos theta + n sin theta) ds,  x(s, c) = X(s) + c n(theta),
// n(theta) = n cos theta - a sin theta; trapezoidal rule on the mesh's own stations.
// For small theta this is the linear field. Velocities are J(theta) theta' and skin
// forces go back as J^T f, i.e. as the bending moments M_k they do on each station's
// rotation, applied to the body as a couple of axial forces +-M_k / t on the two face
// nodes of station k (the linear body's work-conjugate of theta_k) — power is
// consistent between fluid and body. The body's inertia and stiffness stay those of
// the linear reduced model (docs/coupling.md discusses what this leaves out).

#include "mbs/floating_frame_body.h"

#include <vector>

namespace chipflex::coupling
{
class LargeRotationBeamSkin : public mbs::SkinBody<2>
{
public:
  using Vector = Eigen::Vector2d;

  /// @param body a body clamped to ground whose file has the node sets `clamp_set`
  ///        (one end) and `tip_set` (the other), and nodes in matching pairs on the two
  ///        long faces (a structured mesh through the thickness, as `chipflex mesh gate`)
  LargeRotationBeamSkin(mbs::FloatingFrameBody<2>& body, const std::string& clamp_set,
                        const std::string& tip_set);

  std::size_t n_skin_nodes() const override { return body_.n_skin_nodes(); }
  const std::vector<std::array<int, 2>>& skin_faces() const override { return body_.skin_faces(); }
  void skin_positions(std::vector<Vector>& x) const override;
  void skin_velocities(std::vector<Vector>& v) const override;
  void set_skin_forces(const std::vector<Vector>& f) override;

  /// Mean world position of the tip set under the same kinematics (the probe).
  Vector tip_position() const;

private:
  void update_rotations() const;
  Vector place(int station, double c) const; ///< frame coordinates

  mbs::FloatingFrameBody<2>& body_;
  Vector a_, n_, origin_; ///< axis, normal, clamp centre (frame coordinates)
  double thickness_ = 0;
  std::vector<double> s_;         ///< stations along the axis
  std::vector<int> minus_, plus_; ///< face nodes (c = -t/2, +t/2) per station
  std::vector<int> station_;      ///< per skin node
  std::vector<double> c_;         ///< per skin node
  std::vector<int> tip_station_;
  std::vector<double> tip_c_;
  mutable std::vector<double> theta_, theta_dot_;
  mutable std::vector<Vector> centre_; ///< X(s_k)
};
} // namespace chipflex::coupling
