#pragma once
// Contact between bodies and with walls (docs/contact.md): every skin node of a body is
// tested against the faces of every obstacle (sph::WallSurface: the tank, the case's
// walls, permeable barriers) and of every other body's skin, and every obstacle vertex
// against the bodies' faces, found with a hashed cell grid over the faces. A node that
// lies behind the face closest to it (negative signed distance, the foot point inside
// the face, less than `thickness` deep) is in contact.
//
// Normal force: linear spring-dashpot on the overlap delta and its rate,
//     f_n = k delta + c delta',   c = 2 zeta sqrt(k m_c),
//     zeta = -ln e / sqrt(pi^2 + ln^2 e)
// (the exact restitution e of the linear spring-dashpot, e.g. Schwager & Poeschel 2007,
// Phys. Rev. E 75, 051304); m_c is the reduced mass of the pair shared by the contacts
// the pair has this step, so a face landing on N nodes has the damping ratio zeta as a
// whole. The force is that of the spring-dashpot over the whole overlap (it is not
// clipped at zero near the end of the contact), so the restitution is e.
//
// Friction: Coulomb with a tangential spring (Cundall & Strack 1979): each contact keeps
// its tangential displacement xi, the trial force -k_t xi - c_t v_t sticks while it is
// within mu max(f_n, 0); beyond, the force is mu f_n along the trial direction and xi
// is reset to the spring of that force (Luding 2008, Granular Matter 10, 235). A block
// on an incline therefore sticks (no creep) below tan(phi) = mu and slides with the
// kinetic friction mu f_n above.
//
// Forces are evaluated at the positions a little ahead, x + lead dt v, where `lead`
// depends on how the body's integrator turns a load held over the step into motion
// (CoupledBody::contact_lead: 0 for one symplectic-Euler step, about 1 for the
// generalised-alpha step, whose velocity update weights the previous step's load):
// for a linear spring this makes the explicit update area-preserving, so contact
// neither pumps nor drains energy beyond its damping. The forces act on the skin node
// and, with the opposite sign, on the vertices of the face with the barycentric weights
// of the foot point: the weights sum to one, so the forces of every contact sum to zero
// and momentum between bodies is conserved to round-off.

#include "mbs/skin_body.h"
#include "sph/wall_surface.h"

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace chipflex::coupling
{
struct ContactParameters
{
  double restitution = 0.5; ///< e in (0, 1]: normal relative velocity out / in
  double friction = 0.3;    ///< Coulomb coefficient mu (static = kinetic), >= 0
  /// Normal stiffness per contact node, N/m (2D: N/m per metre of depth); 0: derived per
  /// pair, k = m_r / n (pi / (steps dt))^2 with m_r the reduced mass of the pair, n the
  /// larger skin-node count and dt the first step: a contact on all nodes lasts `steps`.
  double stiffness = 0;
  double steps = 20;                ///< time steps per contact for the derived stiffness
  double tangential_ratio = 2. / 7; ///< k_t / k_n (Mindlin's ratio for nu ~ 0.3)
  /// Deepest overlap still counted as contact, m; 0: half the shortest mean skin-edge
  /// length of the bodies. Nodes deeper behind a face are taken to be on its far side.
  double thickness = 0;
};

/// Throws InputError (naming `where`) for a value out of range.
void check(const ContactParameters& p, const std::string& where);

/// zeta of the linear spring-dashpot with restitution e.
double damping_ratio(double restitution);

template <int dim>
class ContactModel
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;

  explicit ContactModel(const ContactParameters& parameters);

  /// An obstacle: its vertices and velocities are read at every compute(), so the
  /// surface may move; it must stay at this address. Returns the obstacle index.
  int add_obstacle(const sph::WallSurface<dim>& wall);
  /// A body (kept by the caller) with its total mass (kg; 2D: per metre of depth) and
  /// the lead of its integrator (CoupledBody::contact_lead; empty: 1/2).
  int add_body(const mbs::SkinBody<dim>& skin, double mass, const std::string& name,
               std::function<double(double)> lead = {});

  /// The contact forces for a step of length dt from the current state (evaluated half a
  /// step ahead). The first call fixes the reference step of a derived stiffness.
  void compute(double dt);

  /// Contact forces on body b's skin nodes (world, N; 2D: N/m) from the last compute().
  const std::vector<Vector>& body_forces(int b) const { return bodies_[b].force; }
  /// Reactions on an obstacle's vertices (the impulse the obstacle takes up).
  const std::vector<Vector>& obstacle_forces(int o) const { return obstacles_[o].force; }

  /// The obstacle's surface (its name and current vertices, where obstacle_forces act).
  const sph::WallSurface<dim>& obstacle(int o) const { return *obstacles_[o].wall; }

  /// A body set inactive (a chip parked by a chip source) touches nothing and takes no
  /// contact force until it is active again.
  void set_active(int b, bool active) { bodies_[b].active = active; }
  bool active(int b) const { return bodies_[b].active; }

  int n_bodies() const { return int(bodies_.size()); }
  int n_obstacles() const { return int(obstacles_.size()); }
  int n_contacts() const { return n_contacts_; }      ///< last compute()
  double max_overlap() const { return max_overlap_; } ///< last compute(), m
  double thickness() const { return thickness_; }
  /// Normal stiffness of body b against obstacle o / against body c (after compute()).
  double stiffness_with_obstacle(int b, int o) const;
  double stiffness_with_body(int b, int c) const;
  const ContactParameters& parameters() const { return parameters_; }

  /// Checkpoint: the reference step and the tangential springs of the live contacts.
  std::vector<double> state() const;
  void restore(const std::vector<double>& state);

private:
  struct Obstacle
  {
    const sph::WallSurface<dim>* wall;
    std::vector<Vector> force;
  };
  struct Body
  {
    const mbs::SkinBody<dim>* skin;
    double mass;
    std::string name;
    std::function<double(double)> lead;
    std::vector<Vector> x, v, xp, force; ///< now, velocity, half a step ahead, contact
    bool active = true;
  };
  /// Surfaces are numbered obstacles first (index o), then bodies (n_obstacles + b).
  /// A contact: node `node` of surface `owner` behind face `face` of surface `partner`.
  struct Contact
  {
    int owner, node, partner, face;
    std::array<double, dim> weights;
    Vector normal;
    double overlap;
  };
  void setup(double dt);
  std::uint64_t cell_key(const Vector& x) const;
  void bin_faces();
  void detect();
  int n_faces(int surface) const;
  const std::array<int, dim>& face(int surface, int f) const;
  const Vector& vertex(int surface, int v) const;
  const Vector& vertex_velocity(int surface, int v) const;
  double pair_mass(int body, int partner) const;
  double pair_stiffness(int body, int partner) const;

  ContactParameters parameters_;
  std::vector<Obstacle> obstacles_;
  std::vector<Body> bodies_;
  std::vector<std::vector<Vector>> obstacle_x_; ///< obstacle vertices half a step ahead
  std::vector<std::vector<Vector>> obstacle_v_; ///< and their velocities
  double reference_dt_ = 0, thickness_ = 0, cell_ = 0;
  bool set_up_ = false;

  // grid: hashed cell -> (surface, face); faces spanning too many cells are kept apart.
  // A hash collision only adds candidates, which the geometric test then rejects.
  using Grid = std::unordered_map<std::uint64_t, std::vector<std::pair<int, int>>>;
  /// Bins surface s's faces, their boxes widened by `widen`; returns the cells it filled
  /// first.
  std::size_t bin_surface(int s, double widen, Grid& grid,
                          std::vector<std::pair<int, int>>& large) const;
  Grid grid_; ///< the bodies' faces, every step
  std::vector<std::pair<int, int>> large_faces_;
  std::size_t used_cells_ = 0; ///< cells the last bin_faces() filled
  /// The obstacles' faces, binned with a slack of half a cell and kept until one of
  /// their vertices has moved by more (binned_obstacle_x_: where they were binned).
  Grid obstacle_grid_;
  std::vector<std::pair<int, int>> obstacle_large_faces_;
  std::vector<std::vector<Vector>> binned_obstacle_x_;

  std::vector<Contact> contacts_;
  /// Tangential spring per live contact, keyed by (owner, node, partner).
  std::map<std::tuple<int, int, int>, Vector> tangential_;
  int n_contacts_ = 0;
  double max_overlap_ = 0;
};
} // namespace chipflex::coupling
