#include "sid_reader.h"

#include <cmath>
#include <fstream>
#include <regex>
#include <stdexcept>

namespace chipflex::test
{
namespace
{
std::string trim(const std::string& s)
{
  const auto a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}
} // namespace

Sid read_sid(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error(path + ": cannot open");
  Sid sid;
  std::vector<std::string> stack; // open blocks
  SidExpansion current;
  std::string line;
  const std::regex entry(R"(m([01])\(\s*(\d+),\s*(\d+)(?:,\s*(\d+))?\)\s*=\s*(\S+))");
  const std::regex setting(R"((\w[\w ()]*?)\s*=\s*(.*))");
  for (int number = 1; std::getline(in, line); ++number)
  {
    const std::string t = trim(line);
    const std::string where = path + ":" + std::to_string(number);
    std::smatch m;
    if (t.empty())
      continue;
    if (t.rfind("end ", 0) == 0)
    {
      const std::string name = t.substr(4);
      if (stack.empty() || stack.back() != name)
        throw std::runtime_error(where + ": 'end " + name + "' closes nothing open");
      stack.pop_back();
      if (name != "part" && name != "modal" && name != "frame" && name != "node" &&
          name != "refmod")
      {
        if (current.structure == 2) // symmetric: the lower triangle was written
        {
          const auto mirror = [](Eigen::MatrixXd& a)
          {
            for (int i = 0; i < a.rows(); ++i)
              for (int j = i + 1; j < a.cols(); ++j)
                a(i, j) = a(j, i);
          };
          mirror(current.m0);
          for (auto& a : current.m1)
            mirror(a);
        }
        if (!stack.empty() && stack.back() == "node")
          sid.nodes.back()[name] = current;
        else
          sid.modal[name] = current;
      }
      continue;
    }
    if (t == "part" || t == "new modal" || t == "refmod" || t == "new frame")
    {
      stack.push_back(t == "new modal" ? "modal" : t == "new frame" ? "frame" : t);
      continue;
    }
    if (t.rfind("new node", 0) == 0)
    {
      stack.push_back("node");
      sid.nodes.emplace_back();
      continue;
    }
    if (std::regex_match(t, m, entry))
    {
      const int i = std::stoi(m[2]) - 1, j = std::stoi(m[3]) - 1;
      const double v = std::stod(m[5]);
      if (i >= current.nrow || j >= current.ncol)
        throw std::runtime_error(where + ": index outside nrow x ncol");
      if (m[1] == "0")
        current.m0(i, j) = v;
      else
      {
        const int k = std::stoi(m[4]) - 1;
        if (k < 0 || k >= int(current.m1.size()))
          throw std::runtime_error(where + ": m1 index outside nq");
        current.m1[k](i, j) = v;
      }
      continue;
    }
    if (std::regex_match(t, m, setting))
    {
      const std::string key = trim(m[1]), value = trim(m[2]);
      const std::string block = stack.empty() ? "" : stack.back();
      if (block == "refmod")
      {
        if (key == "mass")
          sid.mass = std::stod(value);
        else if (key == "nelastq")
          sid.nelastq = std::stoi(value);
        else if (key.rfind("ielastq", 0) == 0)
          sid.ielastq.push_back(value);
      }
      else if (block == "node")
      {
        if (key == "fe node")
          sid.fe_nodes.push_back(std::stoi(value));
      }
      else if (key == "order")
        current.order = std::stoi(value);
      else if (key == "nrow")
        current.nrow = std::stoi(value);
      else if (key == "ncol")
        current.ncol = std::stoi(value);
      else if (key == "nq")
        current.nq = std::stoi(value);
      else if (key == "structure")
      {
        current.structure = std::stoi(value);
        // the header is complete: size the matrices
        current.m0 = Eigen::MatrixXd::Zero(current.nrow, current.ncol);
        current.m1.assign(current.order == 1 ? current.nq : 0,
                          Eigen::MatrixXd::Zero(current.nrow, current.ncol));
      }
      continue;
    }
    // A bare name opens a Taylor expansion.
    stack.push_back(t);
    current = SidExpansion{};
  }
  if (!stack.empty())
    throw std::runtime_error(path + ": '" + stack.back() + "' is not closed");
  return sid;
}

ReducedBodyData body_from_sid(const Sid& sid, int dim)
{
  using Matrix3 = Eigen::Matrix3d;
  const int nq = sid.nelastq, n = static_cast<int>(sid.nodes.size());
  const auto& modal = sid.modal;
  const auto at = [&](const std::string& name) -> const SidExpansion&
  {
    const auto it = modal.find(name);
    if (it == modal.end())
      throw std::runtime_error("the SID has no " + name);
    return it->second;
  };
  // Inverse of the documented forms: J = tr(C) 1 - C  =>  C = tr(J)/2 1 - J.
  const auto second_moment = [](const Matrix3& j)
  { return Matrix3(0.5 * j.trace() * Matrix3::Identity() - j); };
  // The antisymmetric part from the axial vector ax = (C_yz - C_zy, C_zx - C_xz, C_xy - C_yx).
  const auto antisymmetric = [](const Eigen::Vector3d& a)
  {
    Matrix3 w;
    w << 0, a(2), -a(1), -a(2), 0, a(0), a(1), -a(0), 0;
    return Matrix3(0.5 * w);
  };
  // Oe row -(B_xx, B_yy, B_zz, 2 B_xy, 2 B_yz, 2 B_zx), B = tr(G) 1 - sym(G).
  const auto symmetric_from_oe = [&](const Eigen::MatrixXd& row)
  {
    Matrix3 b;
    b << -row(0), -0.5 * row(3), -0.5 * row(5), -0.5 * row(3), -row(1), -0.5 * row(4),
        -0.5 * row(5), -0.5 * row(4), -row(2);
    return second_moment(b); // sym(G) = tr(B)/2 1 - B, the same inversion
  };

  ReducedBodyData b;
  b.dim = dim;
  b.mass = sid.mass;
  b.nodes.resize(n, dim);
  b.psi.resize(dim * n, nq);
  for (int i = 0; i < n; ++i)
  {
    b.nodes.row(i) = sid.nodes[i].at("origin").m0.topRows(dim).transpose();
    b.psi.middleRows(dim * i, dim) = sid.nodes[i].at("phi").m0.topRows(dim);
  }
  const Eigen::Vector3d s0 = at("mdCM").m0;
  b.center_of_mass = s0.head(dim) / b.mass;
  b.translation_coupling.resize(dim, nq);
  for (int k = 0; k < nq; ++k)
    b.translation_coupling.col(k) = at("mdCM").m1[k].topRows(dim);
  const Matrix3 j0 = at("J").m0;
  const Matrix3 c_xx = second_moment(j0);
  b.c_xx = c_xx.topLeftCorner(dim, dim);
  const Eigen::Vector3d c = s0 / b.mass;
  b.inertia_tensor = j0 - b.mass * (c.squaredNorm() * Matrix3::Identity() - c * c.transpose());
  for (int k = 0; k < nq; ++k)
  {
    // J1_k = tr(D) 1 - D with D = C + C^T; Cr0 row k = axial(C(x, psi_k)).
    const Matrix3 sym = 0.5 * second_moment(at("J").m1[k]);
    const Matrix3 full = sym + antisymmetric(at("Cr").m0.row(k).transpose());
    b.c_x_psi.push_back(full.topLeftCorner(dim, dim));
  }
  b.c_psi_psi.assign(nq * nq, Eigen::MatrixXd());
  for (int l = 0; l < nq; ++l)
    for (int k = 0; k < nq; ++k)
    {
      // G = C(psi_l, psi_k): symmetric part from Oe1(k, :, l), antisymmetric from Cr1(k, :, l).
      const Matrix3 g = symmetric_from_oe(at("Oe").m1[l].row(k)) +
                        antisymmetric(at("Cr").m1[l].row(k).transpose());
      b.c_psi_psi[l * nq + k] = g.topLeftCorner(dim, dim); // index l*m+k = C(psi_l, psi_k)
    }
  b.mass_matrix = at("Me").m0;
  b.stiffness_matrix = at("Ke").m0;
  b.frequencies_hz.resize(nq);
  for (int k = 0; k < nq; ++k)
    b.frequencies_hz(k) = std::sqrt(std::max(0.0, b.stiffness_matrix(k, k))) / (2 * M_PI);
  b.mode_kinds.assign(nq, "normal");
  b.model = dim == 2 ? "plane_strain" : "solid_3d";
  b.element_degree = 1;
  return b;
}
} // namespace chipflex::test
