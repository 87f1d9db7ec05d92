// `chipflex export sid`: the SID text of a body read back by a reader written from the
// documented layout (sid_reader.h, independent of common/sid_writer.cc). References: the
// body file itself (mass, centre of mass, inertia tensor, modal mass and stiffness, and
// every C tensor rebuilt from mdCM, J, Cr and Oe, to 1e-12: the text holds 17 digits,
// the inversions are a few flops), and a free body integrated from the SID's data
// against the same body from the file (same equations, so 1e-9 relative).

#include "common/sid_writer.h"
#include "mbs/multibody_system.h"
#include "sid_reader.h"
#include "truss_beam.h"

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace chipflex;

namespace
{
double rel(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b)
{
  REQUIRE(a.rows() == b.rows());
  REQUIRE(a.cols() == b.cols());
  return (a - b).cwiseAbs().maxCoeff() / std::max(b.cwiseAbs().maxCoeff(), 1e-300);
}

test::Sid write_and_read(const ReducedBodyData& body, const SidOptions& options = {})
{
  const std::string path = std::filesystem::temp_directory_path() /
                           ("chipflex_sid_" + std::to_string(::getpid()) + ".SID_FEM");
  write_sid(path, body, options);
  const test::Sid sid = test::read_sid(path);
  std::filesystem::remove(path);
  return sid;
}

template <int dim>
void check_round_trip(const ReducedBodyData& body)
{
  const test::Sid sid = write_and_read(body);
  const ReducedBodyData back = test::body_from_sid(sid, dim);
  const int m = body.n_modes();
  REQUIRE(sid.nelastq == m);
  REQUIRE(static_cast<int>(sid.nodes.size()) == body.n_nodes());
  CHECK(std::abs(back.mass - body.mass) <= 1e-12 * body.mass);
  CHECK(rel(back.center_of_mass, body.center_of_mass) <= 1e-12);
  CHECK(rel(back.inertia_tensor, body.inertia_tensor) <= 1e-12);
  CHECK(rel(back.mass_matrix, body.mass_matrix) <= 1e-12);
  CHECK(rel(back.stiffness_matrix, body.stiffness_matrix) <= 1e-12);
  CHECK(rel(back.nodes, body.nodes) <= 1e-12);
  CHECK(rel(back.psi, body.psi) <= 1e-12);
  CHECK(rel(back.c_xx, body.c_xx) <= 1e-12);
  if (body.translation_coupling.cwiseAbs().maxCoeff() > 0)
    CHECK(rel(back.translation_coupling, body.translation_coupling) <= 1e-12);
  else
    CHECK(back.translation_coupling.cwiseAbs().maxCoeff() <= 1e-14);
  double worst = 0;
  for (int k = 0; k < m; ++k)
    worst = std::max(worst, rel(back.c_x_psi[k], body.c_x_psi[k]));
  double worst_pp = 0, scale_pp = 0;
  for (int k = 0; k < m * m; ++k)
    scale_pp = std::max(scale_pp, body.c_psi_psi[k].cwiseAbs().maxCoeff());
  for (int k = 0; k < m * m; ++k)
    worst_pp = std::max(worst_pp,
                        (back.c_psi_psi[k] - body.c_psi_psi[k]).cwiseAbs().maxCoeff() / scale_pp);
  WARN("mass " << std::abs(back.mass - body.mass) / body.mass << ", inertia "
               << rel(back.inertia_tensor, body.inertia_tensor) << ", Me "
               << rel(back.mass_matrix, body.mass_matrix) << ", Ke "
               << rel(back.stiffness_matrix, body.stiffness_matrix) << ", C(x, psi) " << worst
               << ", C(psi, psi) " << worst_pp);
  CHECK(worst <= 1e-12);
  CHECK(worst_pp <= 1e-12);
}
} // namespace

TEST_CASE("SID export: the reader gets back mass, centre of mass, inertia, Me and Ke", "[sid]")
{
  mbs::test::TrussBeamSpec spec;
  spec.n_modes = 5;
  SECTION("2D clamped (embedded in 3D, z = 0)")
  {
    check_round_trip<2>(mbs::test::make_truss_beam(spec).body);
  }
  SECTION("3D free-free")
  {
    spec.dim = 3;
    spec.n_cells = 6;
    spec.clamped = false;
    check_round_trip<3>(mbs::test::make_truss_beam(spec).body);
  }
  SECTION("a node subset: the frame section holds the set's nodes only")
  {
    const auto body = mbs::test::make_truss_beam(spec).body;
    SidOptions options;
    options.nodes = body.node_sets.at("tip");
    const test::Sid sid = write_and_read(body, options);
    REQUIRE(sid.fe_nodes == options.nodes);
    const auto& origin = sid.nodes.back().at("origin");
    CHECK(origin.m0(0) == body.nodes(options.nodes.back(), 0));
    CHECK(origin.m1.size() == std::size_t(body.n_modes()));
  }
}

TEST_CASE("A free body from the SID integrates as the body file's", "[sid]")
{
  // Free-free 3D truss, a tip force off the centre line plus a frame moment: it
  // translates, spins and vibrates, which exercises every inertia invariant.
  mbs::test::TrussBeamSpec spec;
  spec.dim = 3;
  spec.n_cells = 6;
  spec.n_modes = 4;
  spec.clamped = false;
  const ReducedBodyData body = mbs::test::make_truss_beam(spec).body;
  ReducedBodyData from_sid = test::body_from_sid(write_and_read(body), 3);
  // The SID has no skin; the body needs none to integrate.
  const std::vector<int> tip = body.node_sets.at("tip");
  using V = Eigen::Vector3d;
  std::vector<mbs::MultibodySystem<3>> systems(2);
  systems[0].add_body(std::make_unique<mbs::FloatingFrameBody<3>>(body));
  systems[1].add_body(std::make_unique<mbs::FloatingFrameBody<3>>(from_sid));
  for (auto& s : systems)
  {
    s.body(0).set_node_forces(tip, std::vector<V>(tip.size(), V(0.3, -1.0, 0.5)));
    s.body(0).set_frame_load(V(0, 0, 0), V(0.002, 0.001, -0.003));
  }
  double diff = 0, scale = 0;
  for (int step = 0; step < 400; ++step)
  {
    for (auto& s : systems)
      s.step(5e-5);
    const auto& a = systems[0].body(0);
    const auto& b = systems[1].body(0);
    Eigen::VectorXd x(3 + 9 + a.n_modes()), y(x.size());
    x << a.position(), Eigen::Map<const Eigen::VectorXd>(a.rotation().data(), 9),
        a.modal_coordinates();
    y << b.position(), Eigen::Map<const Eigen::VectorXd>(b.rotation().data(), 9),
        b.modal_coordinates();
    diff = std::max(diff, (x - y).cwiseAbs().maxCoeff());
    scale = std::max(scale, (x - Eigen::VectorXd(x).setZero()).head(3).norm());
  }
  const double angle = Eigen::AngleAxisd(Eigen::Matrix3d(systems[0].body(0).rotation())).angle();
  WARN("largest state difference " << diff << ", frame moved " << scale << " m, turned " << angle
                                   << " rad");
  CHECK(angle > 1e-3); // it did spin
  CHECK(diff <= 1e-9 * std::max(scale, 1.0));
}
