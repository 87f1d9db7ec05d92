// The body file is the contract between fem/ and mbs/: what is written must come back
// bit for bit, and a damaged file must be refused with a message naming the object.

#include "common/input_error.h"
#include "common/reduced_body_file.h"

#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>

using namespace chipflex;

namespace
{
ReducedBodyData make_body(int dim, int n, int m)
{
  ReducedBodyData b;
  b.dim = dim;
  b.youngs_modulus = 1.2e7;
  b.poisson_ratio = 0.4;
  b.density = 1100;
  b.model = dim == 2 ? "plane_strain" : "solid_3d";
  b.mesh_file = "gate.msh";
  b.mesh_hash = "0123456789abcdef";
  b.element_degree = 2;
  b.clamp_set = "clamp";
  b.tool_version = "chipflex test";
  b.nodes = Eigen::MatrixXd::Random(n, dim);
  b.skin_nodes = {0, 1, 2};
  b.skin_faces = Eigen::MatrixXi::Zero(2, dim);
  b.skin_faces(1, 1) = 2;
  b.node_sets["clamp"] = {0, 1};
  b.node_sets["tip"] = {2};
  b.psi = Eigen::MatrixXd::Random(dim * n, m);
  b.frequencies_hz = Eigen::VectorXd::LinSpaced(m, 1, m);
  for (int k = 0; k < m; ++k)
    b.mode_kinds.push_back(k ? "normal" : "static:force:tip:0,-1");
  b.mass_matrix = Eigen::MatrixXd::Identity(m, m);
  b.stiffness_matrix = Eigen::MatrixXd::Random(m, m);
  b.mass = 0.44;
  b.center_of_mass = Eigen::VectorXd::Random(dim);
  b.inertia_tensor = Eigen::Matrix3d::Random();
  b.c_xx = Eigen::MatrixXd::Random(dim, dim);
  b.translation_coupling = Eigen::MatrixXd::Random(dim, m);
  for (int k = 0; k < m; ++k)
    b.c_x_psi.push_back(Eigen::MatrixXd::Random(dim, dim));
  for (int k = 0; k < m * m; ++k)
    b.c_psi_psi.push_back(Eigen::MatrixXd::Random(dim, dim));
  return b;
}
} // namespace

TEST_CASE("body file round trip is exact in 2D and 3D", "[common]")
{
  for (int dim : {2, 3})
  {
    const auto b = make_body(dim, 7, 3);
    const std::string path = "roundtrip_" + std::to_string(dim) + ".h5";
    write_reduced_body(path, b);
    const auto r = read_reduced_body(path);
    CHECK(r.dim == dim);
    CHECK(r.model == b.model);
    CHECK(r.clamp_set == "clamp");
    CHECK(r.nodes == b.nodes);
    CHECK(r.psi == b.psi);
    CHECK(r.skin_nodes == b.skin_nodes);
    CHECK(r.skin_faces == b.skin_faces);
    CHECK(r.node_sets == b.node_sets);
    CHECK(r.mode_kinds == b.mode_kinds);
    CHECK(r.frequencies_hz == b.frequencies_hz);
    CHECK(r.stiffness_matrix == b.stiffness_matrix);
    CHECK(r.inertia_tensor == b.inertia_tensor);
    CHECK(r.translation_coupling == b.translation_coupling);
    REQUIRE(r.c_psi_psi.size() == 9);
    CHECK(r.c_psi_psi[5] == b.c_psi_psi[5]);
    CHECK(r.c_x_psi[2] == b.c_x_psi[2]);
    std::remove(path.c_str());
  }
}

TEST_CASE("a truncated or foreign body file is refused with the file named", "[common]")
{
  const auto b = make_body(2, 5, 2);
  write_reduced_body("good.h5", b);
  {
    std::ifstream in("good.h5", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    std::ofstream out("truncated.h5", std::ios::binary);
    out.write(bytes.data(), bytes.size() / 2);
  }
  {
    std::ofstream out("text.h5");
    out << "not an HDF5 file\n";
  }
  for (const char* bad : {"truncated.h5", "text.h5", "missing.h5"})
  {
    try
    {
      read_reduced_body(bad);
      FAIL("no error for " << bad);
    }
    catch (const InputError& e)
    {
      CHECK(std::string(e.what()).find(bad) != std::string::npos);
    }
  }
  std::remove("good.h5");
  std::remove("truncated.h5");
  std::remove("text.h5");
}
