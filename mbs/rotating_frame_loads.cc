#include "mbs/floating_frame_body.h"

// The fictitious forces of a turning reference frame on a floating-frame body, exact for
// any modal state (the notation of floating_frame_equations.cc).
//
// In a frame turning at Omega (world axes, about the point o) node j feels
//   b_j = -(L r_j + K x_j'),  r_j = x_j - o,  L = [Omega]x^2 + [dOmega/dt]x,  K = 2 [Omega]x.
// With x_j = R + A u_j and x_j' = R' + A (W u_j + Psi_j q') (W = [omega]x, body frame), and
// in body axes L_b = A^T L A, K_b = A^T K A, r = A^T (R - o), r' = A^T R', the virtual work
// sum_ij Ms_ij dx_i . b_j with the identities
//   sum_ij Ms_ij a_i x (M b_j) = axial(C(a, b) M^T),  sum_ij Ms_ij a_i . (M b_j) = tr(M C(b, a))
// gives the generalised forces
//   Q_R   = -A [L_b (m r + s) + K_b (m r' + W s + T q')]
//   Q_th  = -[s x (L_b r + K_b r') + axial(C_uu L_b^T + C_uu W^T K_b^T + C_up K_b^T)]
//   Q_q,k = -[T_k . (L_b r + K_b r') + tr((L_b + K_b W) C(u, psi_k))
//             + 2 B . sum_l q'_l axial C(psi_l, psi_k)],   B = A^T Omega,
// the last from tr([B]x X) = B . axial(X). A body clamped to the (turning) ground keeps
// only the q rows, with R' = 0 and W its clamp's prescribed rotation.

namespace chipflex::mbs
{
template <int dim>
void FloatingFrameBody<dim>::add_frame_inertia(const RotatingFrame& frame, double t,
                                               Eigen::Ref<Eigen::VectorXd> out) const
{
  constexpr int d2 = dim * dim;
  const int m = n_modes_;
  update_deformation_terms();
  const Eigen::Vector3d w = frame.omega(t), dw = frame.alpha(t);
  const Matrix at = rotation_.transpose();
  Matrix l_b, k_b, w_b;
  Omega b; // Omega in body axes (2D: its z component)
  Omega omega = Omega::Zero();
  if (!clamped_)
    omega = v_.template segment<rdim>(dim);
  else if (clamp_rotating_)
    omega = clamp_omega_;
  if constexpr (dim == 2)
  {
    Matrix j;
    j << 0, -1, 1, 0;
    l_b = -w.z() * w.z() * Matrix::Identity() + dw.z() * j; // A^T j A = j in the plane
    k_b = 2 * w.z() * j;
    w_b = omega(0) * j;
    b(0) = w.z();
  }
  else
  {
    const Eigen::Vector3d wb = at * w, dwb = at * dw;
    l_b = wb * wb.transpose() - wb.squaredNorm() * Matrix::Identity() + skew(dwb);
    k_b = 2 * skew(wb);
    w_b = skew(omega);
    b = wb;
  }
  const Vector r = at * (position_ - frame.axis_point.template head<dim>());
  const Vector rd = clamped_ ? Vector::Zero() : Vector(at * v_.template head<dim>());
  const Vector field = l_b * r + k_b * rd;
  const auto qd = v_.tail(m);

  auto fq = out.tail(m);
  const Eigen::Map<const Eigen::MatrixXd> cu(c_upsi_.data(), d2, m);
  const Matrix mq = (l_b + k_b * w_b).transpose(); // tr(M X) = vec(M^T) . vec(X)
  fq.noalias() -= t_.transpose() * field;
  fq.noalias() -= cu.transpose() * Eigen::Map<const Eigen::Matrix<double, d2, 1>>(mq.data());
  tmp_rm_.noalias() = gyro_ * qd;
  const Eigen::Map<const Eigen::Matrix<double, rdim, Eigen::Dynamic>> gyro_q(tmp_rm_.data(), rdim,
                                                                             m);
  fq.noalias() -= 2 * gyro_q.transpose() * b;
  if (clamped_)
    return;

  const Vector tqd = t_ * qd;
  const Eigen::Matrix<double, d2, 1> vec_cup = cu * qd;
  const Matrix c_up = Eigen::Map<const Matrix>(vec_cup.data());
  out.template head<dim>() -=
      rotation_ * (l_b * (mass_ * r + s_) + k_b * (mass_ * rd + w_b * s_ + tqd));
  const Matrix c =
      c_uu_ * l_b.transpose() + c_uu_ * w_b.transpose() * k_b.transpose() + c_up * k_b.transpose();
  if constexpr (dim == 2)
    out(2) -= cross(s_, field) + axial(c);
  else
    out.template segment<3>(3) -= s_.cross(field) + axial(c);
}

template void FloatingFrameBody<2>::add_frame_inertia(const RotatingFrame&, double,
                                                      Eigen::Ref<Eigen::VectorXd>) const;
template void FloatingFrameBody<3>::add_frame_inertia(const RotatingFrame&, double,
                                                      Eigen::Ref<Eigen::VectorXd>) const;
} // namespace chipflex::mbs
