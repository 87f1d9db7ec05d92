#pragma once
// The reduced floating-frame body (FFRF): a body frame (position R in the world, rotation
// A) that moves rigidly, plus small elastic deformation in that frame described by the
// modes of a reduced body file. Node i sits at
//     x_i = R + A u_i,   u_i = xbar_i + Psi_i q,
// generalised velocities v = [R' (world), omega (body frame), q'].
//
// Formulation: the floating frame of reference as in Shabana, "Dynamics of Multibody
// Systems" (3rd ed., ch. 5), written with the nodal mass-weighted invariants of
// Zwoelfer & Gerstmayr (2021), "The nodal-based floating frame of reference
// formulation with modal reduction", Acta Mech 232. Every term of the mass matrix and of
// the quadratic velocity vector is a linear function of the entries of
//     C(a, b) = sum_ij Ms_ij a_i b_j^T      (common/reduced_body_file.h),
// derived in floating_frame_body.cc. The kinematics is linear in q, so these terms are
// exact for any q. Elastic forces: a linear body (format v1, or v2 without /nonlinear) has
// K_red q and no geometric stiffening, so a fast-spinning flexible body softens
// unphysically; a nonlinear body (`chipflex reduce --nonlinear`) has the reduced St
// Venant-Kirchhoff force f(q) = K q + Q:(q q) + C:(q q q) and its tangent
// (common/polynomial_stiffness.h), which couples bending and axial coordinates and gives
// the geometric stiffening under centrifugal load; see docs/mbs.md.
//
// Reference conditions: with a clamp set in the file the modes vanish on the clamp, so
// the frame *is* the clamp (clamp it to ground with clamp_to_ground(), or attach it to
// another body by a FixedJoint); a free-free body's modes are mass-orthogonal to the
// rigid modes, so the frame follows the Tisserand mean axes to first order.
//
// A rigid body is the same class with zero modes (rigid_body.h), so joints, springs and
// the integrator see one body kind.

#include "common/polynomial_stiffness.h"
#include "common/reduced_body_file.h"
#include "common/rotating_frame.h"
#include "mbs/rotation.h"
#include "mbs/skin_body.h"

#include <Eigen/Dense>
#include <map>
#include <string>
#include <vector>

namespace chipflex::mbs
{
/// How the modal damping matrix D_red is built (the file carries none).
enum class DampingKind
{
  none,
  rayleigh, ///< D = alpha M_red + beta K_red
  modal     ///< D = diag(2 zeta omega_k) (mass-normalised modes)
};

struct FloatingFrameOptions
{
  int n_modes = -1; ///< use the first n modes of the file; negative: all
  DampingKind damping = DampingKind::none;
  double rayleigh_mass = 0;       ///< alpha, 1/s
  double rayleigh_stiffness = 0;  ///< beta, s
  double modal_damping_ratio = 0; ///< zeta, same for every mode
};

template <int dim>
class FloatingFrameBody : public SkinBody<dim>
{
public:
  static constexpr int rdim = rotation_dofs<dim>;
  using Vector = Eigen::Matrix<double, dim, 1>;
  using Matrix = Eigen::Matrix<double, dim, dim>;
  using Omega = Eigen::Matrix<double, rdim, 1>;
  using PointJacobian = Eigen::Matrix<double, dim, Eigen::Dynamic>;

  /// Keeps the node coordinates, the modes and the invariants; throws InputError for a
  /// dimension mismatch or inconsistent shapes.
  explicit FloatingFrameBody(const ReducedBodyData& data, const FloatingFrameOptions& options = {});

  // ---- configuration ----------------------------------------------------------------
  /// Frame pose in the world (2D: rotation by angle; 3D: any proper rotation matrix).
  void set_pose(const Vector& position, const Matrix& rotation);
  void set_pose(const Vector& position, double angle); ///< 2D only
  void set_frame_velocity(const Vector& velocity, const Omega& omega_body);
  void set_modal_state(const Eigen::VectorXd& q, const Eigen::VectorXd& q_dot);
  /// Fixes the frame at its current pose: only the modal coordinates remain, and the
  /// equations reduce to M_red q'' + D q' + K_red q = Psi^T A^T f (constant matrices).
  void clamp_to_ground();
  bool clamped_to_ground() const { return clamped_; }
  /// A ground-clamped body whose clamp turns about the frame origin with the prescribed
  /// body-frame angular velocity and acceleration (e.g. a beam on a driven hub, a chip in a
  /// spinning drill): the modal equations gain the inertia loads of the frame motion
  /// (centrifugal, Coriolis, Euler; the same terms as for a floating frame). Set them for
  /// the end of the coming step (generalised-alpha balances at t_n+1), together with the
  /// pose (set_pose) when world loads or positions matter.
  void set_clamp_rotation(const Omega& omega, const Omega& alpha);
  /// True for a body file with the nonlinear (St Venant-Kirchhoff) coefficients.
  bool nonlinear() const { return nonlinear_; }

  const Vector& position() const { return position_; }
  const Matrix& rotation() const { return rotation_; }
  double angle() const { return angle_; } ///< 2D only (unwrapped)
  Vector frame_velocity() const;
  Omega angular_velocity() const; ///< body frame
  const Eigen::VectorXd& modal_coordinates() const { return q_; }
  Eigen::VectorXd modal_velocities() const { return v_.tail(n_modes_); }
  int n_modes() const { return n_modes_; }
  double mass() const { return mass_; }

  // ---- nodes --------------------------------------------------------------------------
  int n_nodes() const { return static_cast<int>(x_ref_.rows()); }
  Vector reference_position(int node) const { return x_ref_.row(node).transpose(); }
  Vector node_position(int node) const;
  Vector node_velocity(int node) const;
  /// Elastic displacement A Psi_i q in world axes (what the full FE model reports when
  /// the frame is clamped to ground at its reference pose).
  Vector node_displacement(int node) const;
  /// Named node set of the file (throws InputError naming the missing set).
  const std::vector<int>& node_set(const std::string& name) const;

  // ---- loads (held until replaced) ----------------------------------------------------
  /// World-frame forces on FE nodes; replaces earlier node or skin forces.
  void set_node_forces(const std::vector<int>& nodes, const std::vector<Vector>& forces);
  /// An extra generalised force on the modal coordinates (e.g. from the full FE loads).
  void set_modal_force(const Eigen::VectorXd& f) { modal_force_ = f; }
  /// Force (world) and moment (world; 2D: scalar about z) on the frame origin.
  void set_frame_load(const Vector& force, const Omega& moment);

  // ---- SkinBody -----------------------------------------------------------------------
  std::size_t n_skin_nodes() const override { return skin_nodes_.size(); }
  const std::vector<std::array<int, dim>>& skin_faces() const override { return skin_faces_; }
  void skin_positions(std::vector<Vector>& x) const override;
  void skin_velocities(std::vector<Vector>& v) const override;
  void set_skin_forces(const std::vector<Vector>& f) override;
  const std::vector<int>& skin_node_ids() const { return skin_nodes_; }

  // ---- what the integrator and joints use (MultibodySystem) -------------------------
  int n_velocities() const { return static_cast<int>(v_.size()); }
  const Eigen::VectorXd& velocities() const { return v_; }
  void set_velocities(const Eigen::Ref<const Eigen::VectorXd>& v) { v_ = v; }
  /// Remembers the current configuration as the base of the next increments.
  void store_base();
  /// Configuration = base composed with increment (translation and q added, rotation
  /// vector applied in the body frame).
  void set_from_base(const Eigen::Ref<const Eigen::VectorXd>& increment);
  void mass_matrix(Eigen::Ref<Eigen::MatrixXd> m) const;
  /// Applied forces minus quadratic velocity vector minus elastic and damping forces.
  void forces(const Vector& gravity, Eigen::Ref<Eigen::VectorXd> f) const;
  /// The applied (not inertial) resultant force and moment about the world origin, both
  /// in world axes (2D: moment about z): what changes the momenta. Free bodies only.
  void applied_frame_load(const Vector& gravity, Vector& force, Omega& moment) const;
  /// Adds the generalised forces of the fictitious accelerations of a turning reference
  /// frame (centrifugal, Coriolis, Euler) at time t to f: the virtual work of
  /// -sum_j Ms_ij (Omega x (Omega x r_j) + 2 Omega x x_j' + dOmega/dt x r_j) over the
  /// nodes, written exactly with the inertia invariants (rotating_frame_loads.cc).
  void add_frame_inertia(const RotatingFrame& frame, double t, Eigen::Ref<Eigen::VectorXd> f) const;
  /// Adds c_k K_t + c_d D_t, the tangent of -forces() used in the Newton matrix (exact
  /// for a ground-clamped body; the elastic part only for a floating one).
  void add_tangent(double c_k, double c_d, Eigen::Ref<Eigen::MatrixXd> s) const;
  /// True when mass matrix and tangent are constant and forces() is linear.
  bool linear() const { return clamped_ && !nonlinear_ && !clamp_rotating_; }

  /// Frame-fixed point p (frame coordinates): world position and d x / d v (dim x nv).
  Vector point_position(const Vector& p) const { return position_ + rotation_ * p; }
  void point_jacobian(const Vector& p, Eigen::Ref<PointJacobian> j) const;
  /// Column offset of the rotational velocities (-1 when clamped to ground).
  int rotation_offset() const { return clamped_ ? -1 : dim; }

  void save_state(std::vector<double>& out) const;
  const double* restore_state(const double* in);

  // ---- diagnostics (world frame, about the world origin) ------------------------------
  Vector linear_momentum() const;
  Omega angular_momentum() const;
  double kinetic_energy() const;
  /// 1/2 q K q (linear), the St Venant-Kirchhoff energy of Psi q (nonlinear).
  double strain_energy() const { return nonlinear_ ? svk_.energy(q_) : 0.5 * q_.dot(k_red_ * q_); }
  /// The elastic force on the modal coordinates, K_red q or f(q).
  Eigen::VectorXd elastic_force() const;

private:
  void update_deformation_terms() const;
  /// Precomputes the load sums of world forces f on nodes with reference coordinates
  /// x_ref (n x dim) and mode rows psi (dim n x m, row = node * dim + component).
  template <class Ref, class Psi>
  void precompute_loads(const Ref& x_ref, const Psi& psi, const std::vector<Vector>& f);

  // constant data
  Eigen::MatrixXd x_ref_; ///< n x dim
  Eigen::MatrixXd psi_;   ///< dim n x m
  std::map<std::string, std::vector<int>> node_sets_;
  std::vector<int> skin_nodes_;
  std::vector<std::array<int, dim>> skin_faces_;
  Eigen::VectorXd skin_ref_; ///< dim n_s
  Eigen::MatrixXd skin_psi_; ///< dim n_s x m
  int n_modes_ = 0;
  double mass_ = 0;
  Vector s0_;         ///< m * centre of mass = sum_ij Ms_ij xbar_j
  Eigen::MatrixXd t_; ///< dim x m, Phi_t^T M Psi
  Matrix c_xx_;
  Eigen::MatrixXd c_xpsi_; ///< dim^2 x m, column k = vec C(x, psi_k)
  Eigen::MatrixXd c_pp_;   ///< dim^2 m x m, block row k, column l = vec C(psi_l, psi_k)
  Eigen::MatrixXd gyro_;   ///< rdim m x m, block row k, column l = axial C(psi_l, psi_k)
  Eigen::MatrixXd m_red_, k_red_, d_red_;
  bool nonlinear_ = false;
  PolynomialStiffness svk_;

  // state
  bool clamped_ = false;
  bool clamp_rotating_ = false;
  Omega clamp_omega_ = Omega::Zero(), clamp_alpha_ = Omega::Zero();
  Vector position_ = Vector::Zero();
  double angle_ = 0;
  Eigen::Quaterniond quaternion_ = Eigen::Quaterniond::Identity();
  Matrix rotation_ = Matrix::Identity();
  Eigen::VectorXd q_;
  Eigen::VectorXd v_;
  Vector base_position_ = Vector::Zero();
  double base_angle_ = 0;
  Eigen::Quaterniond base_quaternion_ = Eigen::Quaterniond::Identity();
  Eigen::VectorXd base_q_;

  // loads
  Vector node_force_sum_ = Vector::Zero();
  Matrix node_force_xf_ = Matrix::Zero(); ///< sum_i xbar_i f_i^T
  Eigen::MatrixXd node_force_gf_;         ///< dim^2 x m, vec sum_i psi_k,i f_i^T
  Eigen::VectorXd modal_force_;
  Vector frame_force_ = Vector::Zero();
  Omega frame_moment_ = Omega::Zero();

  // scratch, refreshed by update_deformation_terms()
  mutable Eigen::VectorXd c_upsi_; ///< dim^2 m: vec C(u, psi_k) for all k
  mutable Vector s_;               ///< sum_ij Ms_ij u_j
  mutable Matrix c_uu_;
  mutable bool deformation_terms_valid_ = false; ///< false whenever q changes
  mutable Eigen::VectorXd tmp_m_, tmp_rm_, tmp_dd_, skin_u_, skin_w_, elastic_;
  mutable Eigen::MatrixXd tangent_;
};
} // namespace chipflex::mbs
