#pragma once
// The adapter between a body's skin (mbs::SkinBody, any body kind) and the moving wall
// the fluid feels (sph::WallSurface). Wall vertex i *is* skin node i, so the fluid's
// reaction on wall vertex i is handed unchanged to skin node i: the fluid distributes
// its reaction to the vertices with the same barycentric weights that placed the
// contact point, and the body maps the nodal forces to generalised forces with the
// transpose of the map that places the nodes (Psi_skin^T, rigid transport). Both maps
// are transposes of the velocity maps, so the power the fluid gives equals the power
// the body receives and the momentum the fluid loses equals what the body gains.

#include "mbs/skin_body.h"
#include "sph/wall_surface.h"

#include <string>
#include <vector>

namespace chipflex::coupling
{
template <int dim>
class SkinWall
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;

  SkinWall(mbs::SkinBody<dim>& body, const std::string& name, sph::WallModel model,
           const sph::LennardJonesParameters& lennard_jones, bool fluid_passes = false);

  /// The wall in the body's current state (call publish() first in each step).
  const sph::WallSurface<dim>& surface() const { return surface_; }
  mbs::SkinBody<dim>& body() { return body_; }
  const mbs::SkinBody<dim>& body() const { return body_; }

  /// Copies the body's skin node positions and velocities into the wall vertices.
  void publish();
  /// Hands the fluid's reaction on the wall vertices, plus the contact forces on the
  /// skin nodes when given, to the body's skin nodes (set_skin_forces replaces, so both
  /// go in one call).
  void deliver(const std::vector<Vector>& vertex_forces,
               const std::vector<Vector>* contact_forces = nullptr);
  /// The fluid's part of the forces last delivered (for output and bookkeeping).
  const std::vector<Vector>& delivered() const { return delivered_; }
  /// The contact part (zeros without contact).
  const std::vector<Vector>& delivered_contact() const { return contact_; }

private:
  mbs::SkinBody<dim>& body_;
  sph::WallSurface<dim> surface_;
  std::vector<Vector> delivered_, contact_, sum_;
};
} // namespace chipflex::coupling
