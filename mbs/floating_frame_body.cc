#include "mbs/floating_frame_body.h"

#include "common/input_error.h"

#include <algorithm>
#include <cmath>

// Data, state, loads and skin of the floating-frame body; its equations of motion (mass
// matrix, quadratic velocity vector, generalised forces) are in floating_frame_equations.cc.

namespace chipflex::mbs
{
namespace
{
template <int dim>
using Mat = Eigen::Matrix<double, dim, dim>;

} // namespace

template <int dim>
FloatingFrameBody<dim>::FloatingFrameBody(const ReducedBodyData& data,
                                          const FloatingFrameOptions& options)
{
  const std::string where = "reduced body (" + data.mesh_file + ")";
  if (data.dim != dim)
    throw InputError(where,
                     "dimension " + std::to_string(data.dim) + ", expected " + std::to_string(dim));
  const int n = data.n_nodes();
  const int m_file = data.n_modes();
  n_modes_ = options.n_modes < 0 ? m_file : std::min(options.n_modes, m_file);
  const int m = n_modes_;
  if (data.nodes.cols() != dim || data.psi.rows() != dim * n ||
      data.translation_coupling.cols() < m || static_cast<int>(data.c_x_psi.size()) < m_file ||
      static_cast<int>(data.c_psi_psi.size()) < m_file * m_file || data.mass_matrix.rows() < m ||
      data.stiffness_matrix.rows() < m || data.c_xx.rows() != dim || data.mass <= 0)
    throw InputError(where, "inconsistent shapes of nodes, modes or inertia invariants");

  x_ref_ = data.nodes;
  psi_ = data.psi.leftCols(m);
  node_sets_ = data.node_sets;
  skin_nodes_ = data.skin_nodes;
  std::vector<int> skin_index(n, -1);
  for (std::size_t s = 0; s < skin_nodes_.size(); ++s)
  {
    if (skin_nodes_[s] < 0 || skin_nodes_[s] >= n)
      throw InputError(where, "skin node id out of range");
    skin_index[skin_nodes_[s]] = static_cast<int>(s);
  }
  for (int f = 0; f < data.skin_faces.rows(); ++f)
  {
    std::array<int, dim> face;
    for (int c = 0; c < dim; ++c)
    {
      const int id = data.skin_faces(f, c);
      if (id < 0 || id >= n || skin_index[id] < 0)
        throw InputError(where, "skin face " + std::to_string(f) + " uses a non-skin node");
      face[c] = skin_index[id];
    }
    skin_faces_.push_back(face);
  }
  const int ns = static_cast<int>(skin_nodes_.size());
  skin_ref_.resize(dim * ns);
  skin_psi_.resize(dim * ns, m);
  for (int s = 0; s < ns; ++s)
  {
    skin_ref_.segment<dim>(dim * s) = x_ref_.row(skin_nodes_[s]).transpose();
    skin_psi_.middleRows(dim * s, dim) = psi_.middleRows(dim * skin_nodes_[s], dim);
  }

  mass_ = data.mass;
  s0_ = data.mass * data.center_of_mass.head<dim>();
  t_ = data.translation_coupling.leftCols(m);
  c_xx_ = data.c_xx;
  constexpr int d2 = dim * dim;
  c_xpsi_.resize(d2, m);
  c_pp_.resize(d2 * m, m);
  gyro_.resize(rdim * m, m);
  for (int k = 0; k < m; ++k)
  {
    c_xpsi_.col(k) = Eigen::Map<const Eigen::VectorXd>(data.c_x_psi[k].data(), d2);
    for (int l = 0; l < m; ++l)
    {
      const Mat<dim> c = data.c_psi_psi[l * m_file + k]; // C(psi_l, psi_k)
      c_pp_.block(d2 * k, l, d2, 1) = Eigen::Map<const Eigen::VectorXd>(c.data(), d2);
      const Eigen::Matrix<double, rdim, 1> ax(axial(c));
      for (int r = 0; r < rdim; ++r) // element-wise: GCC 12 warns on a vectorised 1..3 copy
        gyro_(rdim * k + r, l) = ax(r);
    }
  }
  m_red_ = data.mass_matrix.topLeftCorner(m, m);
  k_red_ = data.stiffness_matrix.topLeftCorner(m, m);
  if (data.nonlinear())
  {
    nonlinear_ = true;
    svk_ = PolynomialStiffness(data.stiffness_matrix, data.quadratic_stiffness,
                               data.cubic_stiffness, m);
  }
  switch (options.damping)
  {
  case DampingKind::none:
    d_red_ = Eigen::MatrixXd::Zero(m, m);
    break;
  case DampingKind::rayleigh:
    d_red_ = options.rayleigh_mass * m_red_ + options.rayleigh_stiffness * k_red_;
    break;
  case DampingKind::modal:
  {
    // D = M Y diag(2 zeta omega_k) Y^T M with K Y = M Y Omega^2, Y^T M Y = 1: zeta in every
    // mode of the reduced pair. chipflex reduce writes K_red diagonal and M_red = 1 (then D
    // is diag(2 zeta omega_k)); a file whose static block is full (written before the
    // static modes were rotated to Ritz vectors) still gets zeta in its true modes rather
    // than on the diagonal's Rayleigh quotients.
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(k_red_, m_red_);
    if (modes.info() != Eigen::Success)
      throw InputError(where, "reduced mass and stiffness: no modal decomposition");
    const Eigen::VectorXd omega = modes.eigenvalues().cwiseMax(0).cwiseSqrt();
    const Eigen::MatrixXd my = m_red_ * modes.eigenvectors();
    d_red_ = my * (2 * options.modal_damping_ratio * omega).asDiagonal() * my.transpose();
    d_red_ = 0.5 * (d_red_ + d_red_.transpose()).eval();
    break;
  }
  }

  q_ = Eigen::VectorXd::Zero(m);
  base_q_ = q_;
  v_ = Eigen::VectorXd::Zero(dim + rdim + m);
  node_force_gf_ = Eigen::MatrixXd::Zero(d2, m);
  modal_force_ = Eigen::VectorXd::Zero(m);
  c_upsi_.resize(d2 * m);
  tmp_m_.resize(m);
  tmp_rm_.resize(rdim * m);
  tmp_dd_.resize(d2);
  skin_u_.resize(dim * ns);
  skin_w_.resize(dim * ns);
  elastic_.resize(m);
}

template <int dim>
void FloatingFrameBody<dim>::set_clamp_rotation(const Omega& omega, const Omega& alpha)
{
  if (!clamped_)
    throw InputError("FloatingFrameBody::set_clamp_rotation", "the body is not clamped to ground");
  clamp_rotating_ = true;
  clamp_omega_ = omega;
  clamp_alpha_ = alpha;
}

template <int dim>
Eigen::VectorXd FloatingFrameBody<dim>::elastic_force() const
{
  Eigen::VectorXd f(n_modes_);
  if (nonlinear_)
    svk_.evaluate(q_, f);
  else
    f.noalias() = k_red_ * q_;
  return f;
}

template <int dim>
void FloatingFrameBody<dim>::set_pose(const Vector& position, const Matrix& rotation)
{
  position_ = position;
  if constexpr (dim == 2)
    angle_ = std::atan2(rotation(1, 0), rotation(0, 0));
  else
    quaternion_ = Eigen::Quaterniond(rotation).normalized();
  if constexpr (dim == 2)
    rotation_ = rotation_matrix(angle_);
  else
    rotation_ = quaternion_.toRotationMatrix();
}

template <int dim>
void FloatingFrameBody<dim>::set_pose(const Vector& position, double angle)
{
  static_assert(dim == 2 || dim == 3);
  if constexpr (dim == 2)
  {
    position_ = position;
    angle_ = angle;
    rotation_ = rotation_matrix(angle);
  }
  else
    throw InputError("FloatingFrameBody<3>::set_pose", "an angle defines a 2D pose only");
}

template <int dim>
void FloatingFrameBody<dim>::set_frame_velocity(const Vector& velocity, const Omega& omega_body)
{
  if (clamped_)
    return;
  v_.template head<dim>() = velocity;
  v_.template segment<rdim>(dim) = omega_body;
}

template <int dim>
void FloatingFrameBody<dim>::set_modal_state(const Eigen::VectorXd& q, const Eigen::VectorXd& q_dot)
{
  q_ = q;
  v_.tail(n_modes_) = q_dot;
  deformation_terms_valid_ = false;
}

template <int dim>
void FloatingFrameBody<dim>::clamp_to_ground()
{
  if (clamped_)
    return;
  const Eigen::VectorXd qd = v_.tail(n_modes_);
  v_ = qd;
  clamped_ = true;
}

template <int dim>
typename FloatingFrameBody<dim>::Vector FloatingFrameBody<dim>::frame_velocity() const
{
  return clamped_ ? Vector::Zero() : Vector(v_.template head<dim>());
}

template <int dim>
typename FloatingFrameBody<dim>::Omega FloatingFrameBody<dim>::angular_velocity() const
{
  return clamped_ ? Omega::Zero() : Omega(v_.template segment<rdim>(dim));
}

template <int dim>
typename FloatingFrameBody<dim>::Vector FloatingFrameBody<dim>::node_position(int node) const
{
  const Vector u = x_ref_.row(node).transpose() + psi_.middleRows(dim * node, dim) * q_;
  return position_ + rotation_ * u;
}

template <int dim>
typename FloatingFrameBody<dim>::Vector FloatingFrameBody<dim>::node_velocity(int node) const
{
  const Vector u = x_ref_.row(node).transpose() + psi_.middleRows(dim * node, dim) * q_;
  Vector w = psi_.middleRows(dim * node, dim) * v_.tail(n_modes_);
  const Omega omega = clamped_ ? clamp_omega_ : Omega(v_.template segment<rdim>(dim));
  if constexpr (dim == 2)
    w += omega(0) * perp(u);
  else
    w += Eigen::Vector3d(omega).cross(u);
  return frame_velocity() + rotation_ * w;
}

template <int dim>
typename FloatingFrameBody<dim>::Vector FloatingFrameBody<dim>::node_displacement(int node) const
{
  return rotation_ * (psi_.middleRows(dim * node, dim) * q_);
}

template <int dim>
const std::vector<int>& FloatingFrameBody<dim>::node_set(const std::string& name) const
{
  const auto it = node_sets_.find(name);
  if (it == node_sets_.end())
    throw InputError("node set '" + name + "'", "not in the reduced body");
  return it->second;
}

template <int dim>
template <class Ref, class Psi>
void FloatingFrameBody<dim>::precompute_loads(const Ref& x_ref, const Psi& psi,
                                              const std::vector<Vector>& forces)
{
  const int n = static_cast<int>(forces.size());
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, dim, Eigen::RowMajor>> f(
      forces.empty() ? nullptr : forces[0].data(), n, dim);
  node_force_sum_ = f.colwise().sum().transpose();
  node_force_xf_.noalias() = x_ref.transpose() * f;
  // vec(G_k)[a + dim b] = sum_i psi(dim i + a, k) f_i[b]: for each component a a small
  // product F^T P_a with P_a the rows dim i + a of psi (a strided view, no copy)
  using Strided =
      Eigen::Map<const Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>>;
  for (int a = 0; a < dim; ++a)
  {
    const Strided p_a(psi.data() + a, n, n_modes_,
                      Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>(psi.outerStride(), dim));
    const Eigen::MatrixXd g = f.transpose() * p_a; // dim x m, row b
    for (int b = 0; b < dim; ++b)
      node_force_gf_.row(a + dim * b) = g.row(b);
  }
}

template <int dim>
void FloatingFrameBody<dim>::set_node_forces(const std::vector<int>& nodes,
                                             const std::vector<Vector>& forces)
{
  if (nodes.size() != forces.size())
    throw InputError("FloatingFrameBody::set_node_forces", "one force per node expected");
  const int n = static_cast<int>(nodes.size());
  Eigen::MatrixXd x(n, dim), psi(dim * n, n_modes_);
  for (int i = 0; i < n; ++i)
  {
    if (nodes[i] < 0 || nodes[i] >= n_nodes())
      throw InputError("FloatingFrameBody::set_node_forces", "node id out of range");
    x.row(i) = x_ref_.row(nodes[i]);
    psi.middleRows(dim * i, dim) = psi_.middleRows(dim * nodes[i], dim);
  }
  precompute_loads(x, psi, forces);
}

template <int dim>
void FloatingFrameBody<dim>::set_frame_load(const Vector& force, const Omega& moment)
{
  frame_force_ = force;
  frame_moment_ = moment;
}

template <int dim>
void FloatingFrameBody<dim>::skin_positions(std::vector<Vector>& x) const
{
  skin_u_.noalias() = skin_psi_ * q_;
  skin_u_ += skin_ref_;
  x.resize(skin_nodes_.size());
  for (std::size_t s = 0; s < x.size(); ++s)
    x[s] = position_ + rotation_ * skin_u_.template segment<dim>(dim * s);
}

template <int dim>
void FloatingFrameBody<dim>::skin_velocities(std::vector<Vector>& v) const
{
  // x' = R' + A (omega x u + Psi q'), u = xbar + Psi q
  v.resize(skin_nodes_.size());
  tmp_m_ = v_.tail(n_modes_);
  skin_w_.noalias() = skin_psi_ * tmp_m_;
  if (clamped_ && !clamp_rotating_)
  {
    for (std::size_t s = 0; s < v.size(); ++s)
      v[s] = rotation_ * skin_w_.template segment<dim>(dim * s);
    return;
  }
  skin_u_.noalias() = skin_psi_ * q_;
  skin_u_ += skin_ref_;
  const Vector r_dot = frame_velocity();
  const Omega omega = clamped_ ? clamp_omega_ : Omega(v_.template segment<rdim>(dim));
  for (std::size_t s = 0; s < v.size(); ++s)
  {
    const Vector u = skin_u_.template segment<dim>(dim * s);
    Vector w = skin_w_.template segment<dim>(dim * s);
    if constexpr (dim == 2)
      w += omega(0) * perp(u);
    else
      w += Eigen::Vector3d(omega).cross(u);
    v[s] = r_dot + rotation_ * w;
  }
}

template <int dim>
void FloatingFrameBody<dim>::set_skin_forces(const std::vector<Vector>& f)
{
  if (f.size() != skin_nodes_.size())
    throw InputError("FloatingFrameBody::set_skin_forces", "one force per skin node expected");
  // skin rows kept contiguous: no gathering, no allocation but the small product
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, dim, Eigen::RowMajor>> x(
      skin_ref_.data(), static_cast<int>(skin_nodes_.size()), dim);
  precompute_loads(x, skin_psi_, f);
}

template <int dim>
void FloatingFrameBody<dim>::store_base()
{
  base_position_ = position_;
  base_angle_ = angle_;
  base_quaternion_ = quaternion_;
  base_q_ = q_;
}

template <int dim>
void FloatingFrameBody<dim>::set_from_base(const Eigen::Ref<const Eigen::VectorXd>& increment)
{
  q_ = base_q_ + increment.tail(n_modes_);
  deformation_terms_valid_ = false;
  if (clamped_)
    return;
  position_ = base_position_ + increment.template head<dim>();
  if constexpr (dim == 2)
  {
    angle_ = base_angle_ + increment(2);
    rotation_ = rotation_matrix(angle_);
  }
  else
  {
    quaternion_ =
        (base_quaternion_ * quaternion_exp(increment.template segment<3>(3))).normalized();
    rotation_ = quaternion_.toRotationMatrix();
  }
}

template <int dim>
void FloatingFrameBody<dim>::point_jacobian(const Vector& p, Eigen::Ref<PointJacobian> j) const
{
  j.setZero();
  if (clamped_)
    return;
  j.template leftCols<dim>().setIdentity();
  if constexpr (dim == 2)
    j.col(2) = rotation_ * perp(p);
  else
    j.template middleCols<3>(3) = -rotation_ * skew(p);
}

template <int dim>
void FloatingFrameBody<dim>::save_state(std::vector<double>& out) const
{
  out.insert(out.end(), position_.data(), position_.data() + dim);
  if constexpr (dim == 2)
    out.push_back(angle_);
  else
    out.insert(out.end(), {quaternion_.w(), quaternion_.x(), quaternion_.y(), quaternion_.z()});
  out.insert(out.end(), q_.data(), q_.data() + q_.size());
  out.insert(out.end(), v_.data(), v_.data() + v_.size());
}

template <int dim>
const double* FloatingFrameBody<dim>::restore_state(const double* in)
{
  position_ = Eigen::Map<const Vector>(in);
  in += dim;
  if constexpr (dim == 2)
  {
    angle_ = *in++;
    rotation_ = rotation_matrix(angle_);
  }
  else
  {
    quaternion_ = Eigen::Quaterniond(in[0], in[1], in[2], in[3]);
    in += 4;
    rotation_ = quaternion_.toRotationMatrix();
  }
  q_ = Eigen::Map<const Eigen::VectorXd>(in, n_modes_);
  in += n_modes_;
  deformation_terms_valid_ = false;
  v_ = Eigen::Map<const Eigen::VectorXd>(in, v_.size());
  return in + v_.size();
}

template <int dim>
typename FloatingFrameBody<dim>::Vector FloatingFrameBody<dim>::linear_momentum() const
{
  Eigen::MatrixXd mm(v_.size(), v_.size());
  mass_matrix(mm);
  if (clamped_)
    return Vector::Zero();
  return (mm * v_).template head<dim>();
}

template <int dim>
typename FloatingFrameBody<dim>::Omega FloatingFrameBody<dim>::angular_momentum() const
{
  // L = sum_ij Ms_ij x_i x x_j' = R x p + A (M v)_theta (the theta rows of M v are the
  // angular momentum about the frame origin in body axes).
  Eigen::MatrixXd mm(v_.size(), v_.size());
  mass_matrix(mm);
  if (clamped_)
    return Omega::Zero();
  const Eigen::VectorXd mv = mm * v_;
  const Vector p = mv.template head<dim>();
  if constexpr (dim == 2)
    return Omega(cross(position_, p) + mv(2));
  else
    return position_.cross(p) + rotation_ * mv.template segment<3>(3);
}

template <int dim>
double FloatingFrameBody<dim>::kinetic_energy() const
{
  Eigen::MatrixXd mm(v_.size(), v_.size());
  mass_matrix(mm);
  return 0.5 * v_.dot(mm * v_);
}

template class FloatingFrameBody<2>;
template class FloatingFrameBody<3>;
} // namespace chipflex::mbs
