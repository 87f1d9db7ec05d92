#pragma once
// One skin made of several bodies' skins (e.g. the links of a rigid chain), so the
// coupling sees a chain as one SkinBody. Nodes and faces are concatenated in body order;
// forces are split back to the bodies. The bodies stay owned by their system.

#include "mbs/floating_frame_body.h"

#include <vector>

namespace chipflex::mbs
{
template <int dim>
class CompositeSkin : public SkinBody<dim>
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  explicit CompositeSkin(std::vector<FloatingFrameBody<dim>*> bodies);

  std::size_t n_skin_nodes() const override { return first_node_.back(); }
  const std::vector<std::array<int, dim>>& skin_faces() const override { return faces_; }
  void skin_positions(std::vector<Vector>& x) const override;
  void skin_velocities(std::vector<Vector>& v) const override;
  void set_skin_forces(const std::vector<Vector>& f) override;

private:
  std::vector<FloatingFrameBody<dim>*> bodies_;
  std::vector<std::size_t> first_node_; ///< n_bodies + 1 prefix sums
  std::vector<std::array<int, dim>> faces_;
  mutable std::vector<Vector> part_;
};
} // namespace chipflex::mbs
