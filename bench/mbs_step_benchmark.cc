// Wall time per implicit (generalised-alpha) step of the body solver: a 3D flexible body
// with 20 modes, clamped to ground (the gate) and free-floating (a chip), and the seed
// paper's 3-link rigid-chain gate. One core, fixed skin loads (as between two fluid
// steps), 1e-5 s steps (a typical fluid step). Without --body the 20-mode body is
// synthetic: a 50 x 2 x 2 node strip with a lumped mass, smooth mass-orthonormalised
// shape functions as modes and 10..200 Hz frequencies.

#include "bench/benchmarks.h"
#include "common/command_line.h"
#include "common/polynomial_stiffness.h"
#include "common/reduced_body_file.h"
#include "mbs/multibody_system.h"
#include "mbs/rigid_chain.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <sstream>
#include <string>

namespace chipflex::bench
{
namespace
{
/// Synthetic 3D body: strip 0.1 x 0.005 x 0.005 m, rubber density, lumped mass,
/// invariants from their definition C(a, b) = sum_i m_i a_i b_i^T.
ReducedBodyData synthetic_body(int n_modes)
{
  const int nx = 50, n = nx * 4;
  const double length = 0.1, w = 0.005, rho = 1100;
  ReducedBodyData d;
  d.dim = 3;
  d.mesh_file = "synthetic strip";
  d.model = "solid_3d";
  d.clamp_set = "clamp";
  d.nodes.resize(n, 3);
  Eigen::VectorXd mass(n);
  for (int i = 0; i < nx; ++i)
    for (int c = 0; c < 4; ++c)
    {
      const int id = 4 * i + c;
      d.nodes.row(id) << length * i / (nx - 1), (c % 2 - 0.5) * w, (c / 2 - 0.5) * w;
      mass(id) = rho * length * w * w / n * ((i == 0 || i == nx - 1) ? 0.5 : 1.0);
      d.skin_nodes.push_back(id);
      if (i == 0)
        d.node_sets["clamp"].push_back(id);
      if (i == nx - 1)
        d.node_sets["tip"].push_back(id);
    }
  d.node_sets["skin"] = d.skin_nodes;
  d.skin_faces.resize(0, 3);
  // modes: bending in y and z, axial and torsion shapes, zero at the clamp, then
  // Gram-Schmidt in the mass inner product
  d.psi = Eigen::MatrixXd::Zero(3 * n, n_modes);
  for (int k = 0; k < n_modes; ++k)
  {
    const int order = k / 4 + 1, kind = k % 4;
    for (int i = 0; i < n; ++i)
    {
      const double s = d.nodes(i, 0) / length;
      const double shape = std::pow(s, 1 + order) + 0.1 * std::sin(order * M_PI * s) * s;
      if (kind < 2)
        d.psi(3 * i + 1 + kind, k) = shape;
      else if (kind == 2)
        d.psi(3 * i, k) = shape;
      else
      {
        d.psi(3 * i + 1, k) = -shape * d.nodes(i, 2) / w;
        d.psi(3 * i + 2, k) = shape * d.nodes(i, 1) / w;
      }
    }
  }
  auto inner = [&](int a, int b)
  {
    double sum = 0;
    for (int i = 0; i < n; ++i)
      sum += mass(i) * d.psi.block<3, 1>(3 * i, a).dot(d.psi.block<3, 1>(3 * i, b));
    return sum;
  };
  for (int k = 0; k < n_modes; ++k)
  {
    for (int j = 0; j < k; ++j)
      d.psi.col(k) -= inner(j, k) * d.psi.col(j);
    d.psi.col(k) /= std::sqrt(inner(k, k));
  }
  d.mass_matrix = Eigen::MatrixXd::Identity(n_modes, n_modes);
  d.stiffness_matrix = Eigen::MatrixXd::Zero(n_modes, n_modes);
  d.frequencies_hz.resize(n_modes);
  for (int k = 0; k < n_modes; ++k)
  {
    d.frequencies_hz(k) = 10.0 * (k + 1);
    d.stiffness_matrix(k, k) = std::pow(2 * M_PI * d.frequencies_hz(k), 2);
  }
  auto rows = [&](int k)
  {
    Eigen::MatrixXd r(n, 3);
    for (int i = 0; i < n; ++i)
      r.row(i) = d.psi.block<3, 1>(3 * i, k).transpose();
    return r;
  };
  auto outer = [&](const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) -> Eigen::MatrixXd
  { return a.transpose() * mass.asDiagonal() * b; };
  d.mass = mass.sum();
  d.center_of_mass = d.nodes.transpose() * mass / d.mass;
  d.c_xx = outer(d.nodes, d.nodes);
  const Eigen::Matrix3d s_c = d.c_xx - d.mass * d.center_of_mass * d.center_of_mass.transpose();
  d.inertia_tensor = s_c.trace() * Eigen::Matrix3d::Identity() - s_c;
  d.translation_coupling.resize(3, n_modes);
  std::vector<Eigen::MatrixXd> r(n_modes);
  for (int k = 0; k < n_modes; ++k)
  {
    r[k] = rows(k);
    d.translation_coupling.col(k) = r[k].transpose() * mass;
    d.c_x_psi.push_back(outer(d.nodes, r[k]));
  }
  for (int a = 0; a < n_modes; ++a)
    for (int b = 0; b < n_modes; ++b)
      d.c_psi_psi.push_back(outer(r[a], r[b]));
  return d;
}

/// The same body with and without the St Venant-Kirchhoff polynomial: a nonlinear file as
/// read and with its /nonlinear part dropped; a linear one as read and with made-up
/// coefficients (deterministic, small enough that Newton converges as for a real body; the
/// cost depends on the number of modes only).
std::pair<ReducedBodyData, ReducedBodyData> linear_and_nonlinear(const ReducedBodyData& data)
{
  ReducedBodyData linear = data, nonlinear = data;
  linear.quadratic_stiffness.clear();
  linear.cubic_stiffness.clear();
  if (!data.nonlinear())
  {
    const int m = data.n_modes();
    const Eigen::VectorXd k = data.stiffness_matrix.diagonal().cwiseAbs().cwiseSqrt();
    nonlinear.quadratic_stiffness = PolynomialStiffness::pack_triples(
        m, [&](int i, int j, int l) { return 1e-2 * k(i) * k(j) * k(l) / k.maxCoeff(); });
    nonlinear.cubic_stiffness = PolynomialStiffness::pack_quadruples(
        m, [&](int i, int j, int l, int n)
        { return 1e-2 * k(i) * k(j) * k(l) * k(n) / (k.maxCoeff() * k.maxCoeff()); });
  }
  return {linear, nonlinear};
}

/// CPU time of this process (one thread here): on a shared machine it excludes the time
/// the scheduler gives to others, which the wall time does not.
double cpu_seconds()
{
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

double last_cpu_us = 0; ///< CPU time per step of the last time_steps() call

template <int dim, class Step>
double time_steps(long steps, Step step)
{
  for (long s = 0; s < steps / 10; ++s) // warm-up: factorisations, caches
    step();
  const double c0 = cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  for (long s = 0; s < steps; ++s)
    step();
  const auto t1 = std::chrono::steady_clock::now();
  last_cpu_us = (cpu_seconds() - c0) * 1e6 / steps;
  return std::chrono::duration<double, std::micro>(t1 - t0).count() / steps;
}

/// The body's state after the timed steps, so that the figure can be cross-checked
/// against another code integrating the same body under the same loads.
template <int dim>
std::string final_state(const mbs::FloatingFrameBody<dim>& body, double time)
{
  const Eigen::VectorXd& q = body.modal_coordinates();
  std::ostringstream s;
  s.precision(9);
  s << "  state at t = " << time << " s: frame at (" << body.position().transpose()
    << "), |q| = " << q.norm() << ", q_1 = " << (q.size() ? q(0) : 0.0) << ", kinetic "
    << body.kinetic_energy() << " J, strain " << body.strain_energy() << " J";
  return s.str();
}

template <int dim>
double flexible_body_step(const ReducedBodyData& data, bool clamped, long steps, bool reuse,
                          double& iterations, std::string& state)
{
  using V = Eigen::Matrix<double, dim, 1>;
  mbs::IntegratorOptions opt;
  opt.rho_infinity = 0.9;
  opt.reuse_newton_matrix = reuse;
  mbs::MultibodySystem<dim> system(opt);
  mbs::FloatingFrameOptions fo;
  fo.damping = mbs::DampingKind::modal;
  fo.modal_damping_ratio = 0.02;
  auto owned = std::make_unique<mbs::FloatingFrameBody<dim>>(data, fo);
  const auto& flexible = *owned;
  const int id = system.add_body(std::move(owned));
  auto& body = system.body(id);
  if (clamped)
    body.clamp_to_ground();
  else
  {
    V v = V::Zero();
    v(0) = 0.1;
    Eigen::Matrix<double, mbs::rotation_dofs<dim>, 1> w;
    w.setConstant(5.0);
    body.set_frame_velocity(v, w);
  }
  std::vector<V> f(body.n_skin_nodes(), V::Zero());
  for (auto& fi : f)
    fi(1) = 1e-3;
  body.set_skin_forces(f);
  long total_iterations = 0;
  const double us = time_steps<dim>(steps,
                                    [&]
                                    {
                                      system.step(1e-5);
                                      total_iterations += system.last_newton_iterations();
                                    });
  iterations = double(total_iterations) / (steps + steps / 10);
  state = final_state<dim>(flexible, 1e-5 * double(steps + steps / 10));
  return us;
}
} // namespace

int mbs_step_benchmark(const Arguments& args)
{
  common::CommandLine cl("chipflex bench mbs [options]",
                         "wall time per implicit step (generalised-alpha, 1e-5 s): a 3D "
                         "flexible body with 20 modes (clamped and free, linear and nonlinear "
                         "St Venant-Kirchhoff) and a 3-link chain; "
                         "target <= 20 us per step of the 20-mode body on one core");
  cl.add_option("--body", "FILE", "reduced body file (default: synthetic 3D strip)");
  cl.add_option("--modes", "N", "modes of the synthetic body", "20");
  cl.add_option("--steps", "N", "timed steps per case", "20000");
  cl.add_flag("--fresh-matrix", "refactorise the Newton matrix every step (no reuse)");
  if (!cl.parse(args))
    return 0;
  const long steps = cl.get_int("--steps");
  const ReducedBodyData data = cl.has("--body") ? read_reduced_body(cl.get("--body"))
                                                : synthetic_body(int(cl.get_int("--modes")));
  std::printf("body: %s, dim %d, %d nodes, %zu skin nodes, %d modes\n", data.mesh_file.c_str(),
              data.dim, data.n_nodes(), data.skin_nodes.size(), data.n_modes());

  const bool reuse = !cl.flag("--fresh-matrix");
  if (!cl.has("--body"))
    std::printf("(synthetic body: lumped mass and made-up modes; pass --body FILE for a "
                "reduced body file)\n");
  double it = 0;
  const auto [linear, nonlinear] = linear_and_nonlinear(data);
  for (const ReducedBodyData* body : {&linear, &nonlinear})
    for (bool clamped : {true, false})
    {
      std::string state;
      const double us = data.dim == 3
                            ? flexible_body_step<3>(*body, clamped, steps, reuse, it, state)
                            : flexible_body_step<2>(*body, clamped, steps, reuse, it, state);
      std::printf("flexible body, %-9s %-18s %8.2f us/step wall, %8.2f us CPU  (%.2f Newton "
                  "iterations/step)\n%s\n",
                  body->nonlinear() ? "nonlinear" : "linear",
                  clamped ? "clamped to ground" : "free-floating", us, last_cpu_us, it,
                  state.c_str());
    }

  // skin exchange with the fluid, once per fluid step
  {
    mbs::MultibodySystem<3> system;
    if (data.dim == 3)
    {
      system.add_body(std::make_unique<mbs::FloatingFrameBody<3>>(data));
      auto& body = system.body(0);
      std::vector<Eigen::Vector3d> x, f(body.n_skin_nodes(), Eigen::Vector3d(0, 1e-3, 0));
      const double us = time_steps<3>(steps / 10,
                                      [&]
                                      {
                                        body.set_skin_forces(f);
                                        body.skin_positions(x);
                                        body.skin_velocities(x);
                                      });
      std::printf("skin exchange (forces in, x and v out) %8.2f us wall, %8.2f us CPU\n", us,
                  last_cpu_us);
    }
  }

  mbs::MultibodySystem<2> chain_system;
  chain_system.set_gravity({0, -9.81});
  // The elastic gate's 3-link chain (Table 2 of its benchmark: 79 mm x 5 mm rubber).
  mbs::RigidChainSpec gate;
  gate.n_links = 3;
  gate.total_length = 0.079;
  gate.thickness = 0.005;
  gate.density = 1100;
  gate.spring_rate = 2.633;
  const mbs::RigidChain chain = mbs::add_rigid_chain(chain_system, gate);
  auto& last = chain_system.body(chain.links.back());
  last.set_node_forces(last.node_set("tip"), {Eigen::Vector2d(0.5, 0), Eigen::Vector2d(0.5, 0)});
  long chain_iterations = 0;
  const double us_chain = time_steps<2>(steps,
                                        [&]
                                        {
                                          chain_system.step(1e-5);
                                          chain_iterations += chain_system.last_newton_iterations();
                                        });
  std::printf("3-link rigid chain (Table 2)      %8.2f us/step wall, %8.2f us CPU  (%.2f Newton "
              "iterations/step)\n",
              us_chain, last_cpu_us, double(chain_iterations) / (steps + steps / 10));
  return 0;
}
} // namespace chipflex::bench
