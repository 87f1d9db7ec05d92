// Floating-frame body: equations of motion against nodal sums, the clamped body against
// exact modal and full-model solutions, conservation laws of a free body, and the
// rigid-elastic coupling during spin-up.
#include "mbs/floating_frame_body.h"
#include "mbs/multibody_system.h"
#include "truss_beam.h"

#include <catch2/catch.hpp>
#include <random>

using namespace chipflex;
using namespace chipflex::mbs;
using chipflex::mbs::test::make_truss_beam;
using chipflex::mbs::test::TrussBeam;
using chipflex::mbs::test::TrussBeamSpec;

namespace
{
/// Reference by brute force over the nodes: generalised mass matrix sum Ms_ij B_i^T B_j
/// and generalised forces sum B_i^T f_i + sum Ms_ij B_i^T (g - b_j), with B_i = dx_i/dv and
/// b_j the velocity-dependent part of x_j'' (centripetal + Coriolis), from the kinematics
/// x_j'' = R'' + A (alpha x u + Psi q'' + omega x (omega x u) + 2 omega x Psi q').
template <int dim>
void nodal_reference(const FloatingFrameBody<dim>& body, const Eigen::MatrixXd& ms,
                     const Eigen::MatrixXd& psi, const Eigen::MatrixXd& x_ref,
                     const std::vector<Eigen::Matrix<double, dim, 1>>& f,
                     const Eigen::Matrix<double, dim, 1>& g, Eigen::MatrixXd& m_ref,
                     Eigen::VectorXd& f_ref)
{
  using V = Eigen::Matrix<double, dim, 1>;
  const int n = static_cast<int>(x_ref.rows());
  const int nv = body.n_velocities();
  const int m = body.n_modes();
  const auto a = body.rotation();
  const Eigen::VectorXd q = body.modal_coordinates(), qd = body.modal_velocities();
  std::vector<Eigen::MatrixXd> b(n);
  std::vector<V> acc(n);
  for (int i = 0; i < n; ++i)
  {
    const Eigen::MatrixXd psi_i = psi.middleRows(dim * i, dim);
    const V u = x_ref.row(i).transpose() + psi_i * q;
    const V pq = psi_i * qd;
    b[i] = Eigen::MatrixXd::Zero(dim, nv);
    b[i].leftCols(dim).setIdentity();
    // columns of B for the rotations: A (e_c x u); copied element-wise (GCC 12 warns
    // about vectorised copies of 2- and 3-vector temporaries into dynamic blocks)
    Eigen::Matrix<double, dim, rotation_dofs<dim>> b_rot;
    if constexpr (dim == 2)
    {
      const double w = body.angular_velocity()(0);
      b_rot.col(0) = a * Eigen::Vector2d(-u.y(), u.x());
      acc[i] = a * (-w * w * u + 2 * w * Eigen::Vector2d(-pq.y(), pq.x()));
    }
    else
    {
      const Eigen::Vector3d w = body.angular_velocity();
      for (int c = 0; c < 3; ++c)
        b_rot.col(c) = a * Eigen::Vector3d::Unit(c).cross(u);
      acc[i] = a * (w.cross(w.cross(u)) + 2 * w.cross(pq));
    }
    for (int r = 0; r < dim; ++r)
      for (int c = 0; c < rotation_dofs<dim>; ++c)
        b[i](r, dim + c) = b_rot(r, c);
    b[i].rightCols(m) = a * psi_i;
  }
  m_ref = Eigen::MatrixXd::Zero(nv, nv);
  f_ref = Eigen::VectorXd::Zero(nv);
  for (int i = 0; i < n; ++i)
  {
    f_ref += b[i].transpose() * f[i];
    for (int j = 0; j < n; ++j)
    {
      if (ms(i, j) == 0)
        continue;
      m_ref += ms(i, j) * b[i].transpose() * b[j];
      f_ref += ms(i, j) * b[i].transpose() * (g - acc[j]);
    }
  }
}

/// A free-free truss beam of `n_cells` cells reduced to `n_modes` modes.
TrussBeam free_truss_beam(int dim, int n_cells, int n_modes)
{
  TrussBeamSpec spec;
  spec.dim = dim;
  spec.n_cells = n_cells;
  spec.n_modes = n_modes;
  spec.clamped = false;
  return make_truss_beam(spec);
}

/// A free body put in motion: at `position` (every coordinate), turned by `angle` (3D:
/// about `axis`), moving with `velocity` (every coordinate) and a random angular velocity,
/// with large random modal amplitudes and rates (several mm of deformation, so that the
/// q-dependent terms count). Returns q.
template <int dim>
Eigen::VectorXd put_in_motion(FloatingFrameBody<dim>& body, std::mt19937& rng, double angle,
                              const Eigen::Vector3d& axis, double position, double velocity)
{
  using V = Eigen::Matrix<double, dim, 1>;
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::Matrix<double, dim, dim> rot;
  if constexpr (dim == 2)
    rot = rotation_matrix(angle);
  else
    rot = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  body.set_pose(V::Constant(position), rot);
  Eigen::Matrix<double, rotation_dofs<dim>, 1> w;
  for (int c = 0; c < w.size(); ++c)
    w(c) = 3 * u(rng);
  body.set_frame_velocity(V::Constant(velocity), w);
  const int m = body.n_modes();
  Eigen::VectorXd q(m), qd(m);
  for (int k = 0; k < m; ++k)
  {
    q(k) = 5e-4 * u(rng);
    qd(k) = 0.05 * u(rng);
  }
  body.set_modal_state(q, qd);
  return q;
}

template <int dim>
void check_equations_of_motion(int n_cells, int n_modes)
{
  using V = Eigen::Matrix<double, dim, 1>;
  const auto beam = free_truss_beam(dim, n_cells, n_modes);
  FloatingFrameBody<dim> body(beam.body);
  const int m = body.n_modes();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const Eigen::VectorXd q =
      put_in_motion<dim>(body, rng, dim == 2 ? 0.7 : 0.9, Eigen::Vector3d(1, 2, 3), 0.3, 0.2);
  std::vector<V> f(body.n_nodes());
  std::vector<int> ids(body.n_nodes());
  for (int i = 0; i < body.n_nodes(); ++i)
  {
    ids[i] = i;
    for (int c = 0; c < dim; ++c)
      f[i](c) = u(rng);
  }
  body.set_node_forces(ids, f);
  const V g = V::Constant(-9.81);

  Eigen::MatrixXd m_ref;
  Eigen::VectorXd f_ref;
  nodal_reference<dim>(body, beam.scalar_mass, beam.body.psi.leftCols(m), beam.body.nodes, f, g,
                       m_ref, f_ref);
  const int nv = body.n_velocities();
  Eigen::MatrixXd mm(nv, nv);
  body.mass_matrix(mm);
  Eigen::VectorXd fb(nv);
  body.forces(g, fb);
  fb.tail(m) += beam.body.stiffness_matrix.topLeftCorner(m, m) * q; // elastic part is not nodal
  // Round-off only: a wrong term is off by O(1). The force check allows 1e-10 because
  // the nodal sums and the invariants add the large gravity and quadratic-velocity terms in
  // other orders (with AVX-512 FMA the 3D case differs by 2.4e-11 relative).
  CHECK((mm - m_ref).norm() <= 1e-11 * m_ref.norm());
  CHECK((fb - f_ref).norm() <= 1e-10 * f_ref.norm());
  // kinetic energy and momenta against the nodal sums
  double t_ref = 0;
  V p_ref = V::Zero();
  Eigen::Matrix<double, rotation_dofs<dim>, 1> l_ref;
  l_ref.setZero();
  for (int i = 0; i < body.n_nodes(); ++i)
    for (int j = 0; j < body.n_nodes(); ++j)
    {
      const double mij = beam.scalar_mass(i, j);
      t_ref += 0.5 * mij * body.node_velocity(i).dot(body.node_velocity(j));
      p_ref += mij * body.node_velocity(j);
      l_ref += Eigen::Matrix<double, rotation_dofs<dim>, 1>(
          mij * cross(body.node_position(i), body.node_velocity(j)));
    }
  CHECK(std::abs(body.kinetic_energy() - t_ref) <= 1e-12 * t_ref);
  CHECK((body.linear_momentum() - p_ref).norm() <= 1e-12 * p_ref.norm());
  CHECK((body.angular_momentum() - l_ref).norm() <= 1e-12 * l_ref.norm());
}
} // namespace

TEST_CASE("FFRF mass matrix, quadratic velocity vector and loads equal the nodal sums (2D)",
          "[mbs][ffrf]")
{
  // reference: the virtual-work sum over nodes with the consistent mass matrix
  check_equations_of_motion<2>(6, 8);
}

TEST_CASE("FFRF mass matrix, quadratic velocity vector and loads equal the nodal sums (3D)",
          "[mbs][ffrf]")
{
  check_equations_of_motion<3>(4, 10);
}

namespace
{
/// The fictitious forces of a turning frame (spinning up: centrifugal, Coriolis and Euler
/// at once) against the virtual work of the nodal fictitious forces sum_j Ms_ij b_j.
template <int dim>
void check_frame_inertia(int n_cells, int n_modes)
{
  using V = Eigen::Matrix<double, dim, 1>;
  const auto beam = free_truss_beam(dim, n_cells, n_modes);
  FloatingFrameBody<dim> body(beam.body);
  const int m = body.n_modes();
  std::mt19937 rng(11);
  put_in_motion<dim>(body, rng, dim == 2 ? -0.4 : 1.3, Eigen::Vector3d(-1, 2, 0.5), 0.2, -0.3);

  RotatingFrame frame;
  frame.angular_velocity = dim == 2 ? Eigen::Vector3d(0, 0, 7) : Eigen::Vector3d(2, -4, 5);
  frame.axis_point = Eigen::Vector3d(0.05, -0.1, 0.02);
  frame.spin_up_time = 1;
  const double t = 0.4; // spinning up: dOmega/dt != 0
  std::vector<V> b(body.n_nodes()), f(body.n_nodes(), V::Zero());
  for (int j = 0; j < body.n_nodes(); ++j)
    b[j] = frame.acceleration<dim>(t, body.node_position(j), body.node_velocity(j));
  for (int i = 0; i < body.n_nodes(); ++i)
    for (int j = 0; j < body.n_nodes(); ++j)
      f[i] += beam.scalar_mass(i, j) * b[j];

  // The fictitious part alone on both sides: the nodal sums with and without the nodal
  // fictitious forces, against add_frame_inertia().
  Eigen::MatrixXd m_ref;
  Eigen::VectorXd f_ref, f_ref0;
  const Eigen::MatrixXd psi = beam.body.psi.leftCols(m);
  nodal_reference<dim>(body, beam.scalar_mass, psi, beam.body.nodes, f, V::Zero(), m_ref, f_ref);
  nodal_reference<dim>(body, beam.scalar_mass, psi, beam.body.nodes,
                       std::vector<V>(body.n_nodes(), V::Zero()), V::Zero(), m_ref, f_ref0);
  f_ref -= f_ref0;
  Eigen::VectorXd fb = Eigen::VectorXd::Zero(body.n_velocities());
  body.add_frame_inertia(frame, t, fb);
  // Round-off only: a wrong or missing term is off by O(1) of its row.
  for (int r = 0; r < fb.size(); ++r)
    CHECK(std::abs(fb(r) - f_ref(r)) <= 1e-10 * f_ref.cwiseAbs().maxCoeff());
}
} // namespace

TEST_CASE("FFRF fictitious forces of a turning frame equal the nodal sums (2D)",
          "[mbs][ffrf][rotating_frame]")
{
  check_frame_inertia<2>(6, 8);
}

TEST_CASE("FFRF fictitious forces of a turning frame equal the nodal sums (3D)",
          "[mbs][ffrf][rotating_frame]")
{
  check_frame_inertia<3>(4, 10);
}
