#include "mbs/floating_frame_body.h"

// Derivation of the equations of motion (one derivation for 2D and 3D).
//
// Node velocity and acceleration with w_i = omega x u_i + Psi_i q' (body frame):
//   x_i'  = R' + A w_i
//   x_i'' = R'' + A (alpha x u_i + Psi_i q'' + omega x (omega x u_i) + 2 omega x Psi_i q')
// Virtual displacements dx_i = dR + A (dtheta x u_i + Psi_i dq). The principle of virtual
// work with the consistent mass matrix, sum_ij Ms_ij dx_i . x_j'' = sum_i dx_i . f_i,
// gives M(q) [R''; alpha; q''] + h(v, q) = Q. With s = sum_ij Ms_ij u_j = m c + T q,
// C_u_psik = C(u, psi_k) = C(x, psi_k) + sum_l q_l C(psi_l, psi_k),
// C_uu = C(u, u) = C(x, x) + sum_k q_k (C(x, psi_k) + C(u, psi_k)^T) and the identities
//   sum_ij Ms_ij a_i x b_j = axial(C(a, b)),  sum_ij Ms_ij a_i . b_j = tr C(a, b):
//
// mass matrix (symmetric):
//   M_RR = m I          M_Rth = -A skew(s)  [2D: A perp(s)]          M_Rq = A T
//   M_thth = J = tr(C_uu) I - C_uu  [2D: tr C_uu]    M_thq[:, k] = axial C_u_psik
//   M_qq = M_red
// quadratic velocity vector h (moved to the right-hand side with a minus sign):
//   h_R  = A (omega x (omega x s) + 2 omega x T q')          [2D: A(-w^2 s + 2 w perp(T q'))]
//   h_th = omega x J omega + 2 (tr(C_up) omega - C_up^T omega),  C_up = sum_k q'_k C_u_psik
//                                                           [2D: 2 w tr C_up]
//   h_q,k = omega^T C_u_psik omega - |omega|^2 tr C_u_psik + 2 omega . sum_l q'_l axial C(psi_l,
//   psi_k)
//                                                           [2D: -w^2 tr C_u_psik + 2 w (...)]
// (sum Ms_ij u_i x (omega x (omega x u_j)) = -omega x (C_uu omega) = omega x J omega because
// C_uu is symmetric; sum Ms_ij psi_k,i . (omega x psi_l,j) = omega . axial C(psi_l, psi_k).)
// generalised forces of world nodal forces f_i, with X_f = sum_i xbar_i f_i^T and
// G_k = sum_i psi_k,i f_i^T (precomputed when the forces are set):
//   Q_R = sum_i f_i,  Q_th = sum_i u_i x A^T f_i = axial((X_f + sum_k q_k G_k) A),
//   Q_q,k = sum_i psi_k,i . A^T f_i = tr(A G_k)
// gravity g: Q_R = m g, Q_th = s x A^T g, Q_q = T^T A^T g.
// Elastic force: K_red q, or for a nonlinear body the reduced St Venant-Kirchhoff force
// f(q) (common/polynomial_stiffness.h); the kinematics x = R + A (xbar + Psi q) is the same,
// so none of the inertia terms above changes.
// A ground-clamped body on a prescribed rotation (set_clamp_rotation) keeps the q rows
// with omega and alpha given: Q_q - h_q(omega, q, q') - M_thq^T alpha.

namespace chipflex::mbs
{
namespace
{
template <int dim>
using Mat = Eigen::Matrix<double, dim, dim>;

template <int dim>
Eigen::Map<const Mat<dim>> as_matrix(const double* p)
{
  return Eigen::Map<const Mat<dim>>(p);
}
} // namespace

template <int dim>
void FloatingFrameBody<dim>::update_deformation_terms() const
{
  if (deformation_terms_valid_)
    return;
  deformation_terms_valid_ = true;
  constexpr int d2 = dim * dim;
  const int m = n_modes_;
  s_ = s0_ + t_ * q_;
  c_upsi_.noalias() = c_pp_ * q_;
  c_upsi_ += Eigen::Map<const Eigen::VectorXd>(c_xpsi_.data(), d2 * m);
  const Eigen::Map<const Eigen::MatrixXd> cu(c_upsi_.data(), d2, m);
  Eigen::Matrix<double, d2, 1> a = c_xpsi_ * q_, b = cu * q_;
  c_uu_ = c_xx_ + as_matrix<dim>(a.data()) + as_matrix<dim>(b.data()).transpose();
}

template <int dim>
void FloatingFrameBody<dim>::mass_matrix(Eigen::Ref<Eigen::MatrixXd> mm) const
{
  const int m = n_modes_;
  if (clamped_)
  {
    mm = m_red_;
    return;
  }
  update_deformation_terms();
  constexpr int d2 = dim * dim;
  constexpr int f = dim + rdim;
  mm.setZero();
  mm.template topLeftCorner<dim, dim>() = mass_ * Matrix::Identity();
  if constexpr (dim == 2)
  {
    mm.template block<2, 1>(0, 2) = rotation_ * perp(s_);
    mm(2, 2) = c_uu_.trace();
  }
  else
  {
    mm.template block<3, 3>(0, 3) = -rotation_ * skew(s_);
    mm.template block<3, 3>(3, 3) = c_uu_.trace() * Matrix::Identity() - c_uu_;
  }
  mm.block(0, f, dim, m).noalias() = rotation_ * t_;
  for (int k = 0; k < m; ++k)
  {
    const Eigen::Matrix<double, rdim, 1> ax(
        axial(Mat<dim>(as_matrix<dim>(c_upsi_.data() + d2 * k))));
    for (int r = 0; r < rdim; ++r) // element-wise: GCC 12 warns on a vectorised 1..3 copy
      mm(dim + r, f + k) = ax(r);
  }
  mm.bottomRightCorner(m, m) = m_red_;
  mm.block(dim, 0, rdim, dim) = mm.block(0, dim, dim, rdim).transpose();
  mm.block(f, 0, m, f) = mm.block(0, f, f, m).transpose();
}

template <int dim>
void FloatingFrameBody<dim>::forces(const Vector& gravity, Eigen::Ref<Eigen::VectorXd> out) const
{
  constexpr int d2 = dim * dim;
  const int m = n_modes_;
  const Matrix at = rotation_.transpose();
  const Eigen::Map<const Eigen::Matrix<double, d2, 1>> vec_at(at.data());
  const Vector g_body = at * gravity;
  const auto qd = v_.tail(m);

  auto fq = out.tail(m);
  fq.noalias() = node_force_gf_.transpose() * vec_at;
  fq.noalias() += t_.transpose() * g_body;
  if (nonlinear_)
  {
    svk_.evaluate(q_, elastic_);
    fq -= elastic_;
  }
  else
    fq.noalias() -= k_red_ * q_;
  fq.noalias() -= d_red_ * qd;
  fq += modal_force_;
  if (clamped_ && !clamp_rotating_)
    return;

  update_deformation_terms();
  const Eigen::Map<const Eigen::MatrixXd> cu(c_upsi_.data(), d2, m);
  if (clamped_) // prescribed rotation of the clamp: its inertia loads on the modes
  {
    tmp_rm_.noalias() = gyro_ * qd;
    const Eigen::Map<const Eigen::Matrix<double, rdim, Eigen::Dynamic>> gyro_q(tmp_rm_.data(), rdim,
                                                                               m);
    for (int k = 0; k < m; ++k)
    {
      const Eigen::Matrix<double, rdim, 1> ax(
          axial(Mat<dim>(as_matrix<dim>(c_upsi_.data() + d2 * k))));
      fq(k) -= ax.dot(clamp_alpha_);
    }
    if constexpr (dim == 2)
    {
      const double w = clamp_omega_(0);
      fq += w * w * (cu.row(0) + cu.row(3)).transpose();
      fq.noalias() -= 2 * w * gyro_q.transpose();
    }
    else
    {
      const Eigen::Vector3d w = clamp_omega_;
      const Matrix ww = w * w.transpose() - w.squaredNorm() * Matrix::Identity();
      const Eigen::Map<const Eigen::Matrix<double, d2, 1>> vec_ww(ww.data());
      fq.noalias() -= cu.transpose() * vec_ww;
      fq.noalias() -= 2 * gyro_q.transpose() * w;
    }
    return;
  }
  const Vector tqd = t_ * qd;
  Eigen::Matrix<double, d2, 1> vec_cup = cu * qd;
  const Matrix c_up = as_matrix<dim>(vec_cup.data());
  Eigen::Matrix<double, d2, 1> vec_gq = node_force_gf_ * q_;
  const Matrix load_moment = (node_force_xf_ + as_matrix<dim>(vec_gq.data())) * rotation_;
  tmp_rm_.noalias() = gyro_ * qd; // block k: sum_l q'_l axial C(psi_l, psi_k)
  const Eigen::Map<const Eigen::Matrix<double, rdim, Eigen::Dynamic>> gyro_q(tmp_rm_.data(), rdim,
                                                                             m);
  if constexpr (dim == 2)
  {
    const double w = v_(2);
    out.template head<2>() = node_force_sum_ + mass_ * gravity + frame_force_ -
                             rotation_ * (-w * w * s_ + 2 * w * perp(tqd));
    out(2) = axial(load_moment) + cross(s_, g_body) + frame_moment_(0) - 2 * w * c_up.trace();
    // -w^2 tr C_u_psik: rows 0 and 3 of the vec are the diagonal
    fq += w * w * (cu.row(0) + cu.row(3)).transpose();
    fq.noalias() -= 2 * w * gyro_q.transpose();
  }
  else
  {
    const Eigen::Vector3d w = v_.template segment<3>(3);
    const Matrix j = c_uu_.trace() * Matrix::Identity() - c_uu_;
    out.template head<3>() = node_force_sum_ + mass_ * gravity + frame_force_ -
                             rotation_ * (w.cross(w.cross(s_)) + 2 * w.cross(tqd));
    out.template segment<3>(3) = axial(load_moment) + s_.cross(g_body) + at * frame_moment_ -
                                 w.cross(j * w) - 2 * (c_up.trace() * w - c_up.transpose() * w);
    const Matrix ww = w * w.transpose() - w.squaredNorm() * Matrix::Identity();
    const Eigen::Map<const Eigen::Matrix<double, d2, 1>> vec_ww(ww.data());
    fq.noalias() -= cu.transpose() * vec_ww;
    fq.noalias() -= 2 * gyro_q.transpose() * w;
  }
}

template <int dim>
void FloatingFrameBody<dim>::applied_frame_load(const Vector& gravity, Vector& force,
                                                Omega& moment) const
{
  // Q_R and the world moment about the origin, R x Q_R + A Q_theta (same terms as forces())
  constexpr int d2 = dim * dim;
  update_deformation_terms();
  const Matrix at = rotation_.transpose();
  force = node_force_sum_ + mass_ * gravity + frame_force_;
  Eigen::Matrix<double, d2, 1> vec_gq = node_force_gf_ * q_;
  const Matrix load_moment = (node_force_xf_ + as_matrix<dim>(vec_gq.data())) * rotation_;
  if constexpr (dim == 2)
    moment(0) = cross(position_, force) + axial(load_moment) + cross(s_, Vector(at * gravity)) +
                frame_moment_(0);
  else
    moment = position_.cross(force) + rotation_ * (axial(load_moment) + s_.cross(at * gravity)) +
             frame_moment_;
}

template <int dim>
void FloatingFrameBody<dim>::add_tangent(double c_k, double c_d,
                                         Eigen::Ref<Eigen::MatrixXd> s) const
{
  const int m = n_modes_;
  if (nonlinear_)
  {
    svk_.evaluate(q_, elastic_, &tangent_);
    s.bottomRightCorner(m, m) += c_k * tangent_ + c_d * d_red_;
  }
  else
    s.bottomRightCorner(m, m) += c_k * k_red_ + c_d * d_red_;
}

template void FloatingFrameBody<2>::update_deformation_terms() const;
template void FloatingFrameBody<2>::mass_matrix(Eigen::Ref<Eigen::MatrixXd>) const;
template void FloatingFrameBody<2>::forces(const FloatingFrameBody<2>::Vector&,
                                           Eigen::Ref<Eigen::VectorXd>) const;
template void FloatingFrameBody<2>::applied_frame_load(const FloatingFrameBody<2>::Vector&,
                                                       FloatingFrameBody<2>::Vector&,
                                                       FloatingFrameBody<2>::Omega&) const;
template void FloatingFrameBody<2>::add_tangent(double, double, Eigen::Ref<Eigen::MatrixXd>) const;
template void FloatingFrameBody<3>::update_deformation_terms() const;
template void FloatingFrameBody<3>::mass_matrix(Eigen::Ref<Eigen::MatrixXd>) const;
template void FloatingFrameBody<3>::forces(const FloatingFrameBody<3>::Vector&,
                                           Eigen::Ref<Eigen::VectorXd>) const;
template void FloatingFrameBody<3>::applied_frame_load(const FloatingFrameBody<3>::Vector&,
                                                       FloatingFrameBody<3>::Vector&,
                                                       FloatingFrameBody<3>::Omega&) const;
template void FloatingFrameBody<3>::add_tangent(double, double, Eigen::Ref<Eigen::MatrixXd>) const;
} // namespace chipflex::mbs
