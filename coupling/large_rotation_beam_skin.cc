#include "coupling/large_rotation_beam_skin.h"

#include "common/input_error.h"

#include <algorithm>
#include <cmath>

namespace chipflex::coupling
{
namespace
{
Eigen::Vector2d mean_of(const mbs::FloatingFrameBody<2>& body, const std::vector<int>& nodes)
{
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int i : nodes)
    sum += body.reference_position(i);
  return sum / double(nodes.size());
}
} // namespace

LargeRotationBeamSkin::LargeRotationBeamSkin(mbs::FloatingFrameBody<2>& body,
                                             const std::string& clamp_set,
                                             const std::string& tip_set)
    : body_(body)
{
  if (!body.clamped_to_ground())
    throw InputError("large-rotation skin", "the body must be clamped to ground");
  origin_ = mean_of(body, body.node_set(clamp_set));
  const Vector tip = mean_of(body, body.node_set(tip_set));
  a_ = (tip - origin_).normalized();
  n_ = Vector(-a_.y(), a_.x());
  const auto& skin = body.skin_node_ids();
  double c_max = 0;
  for (int i : skin)
    c_max = std::max(c_max, std::abs((body.reference_position(i) - origin_).dot(n_)));
  thickness_ = 2 * c_max;
  const double length = (tip - origin_).norm();
  const double tol = 1e-6 * length;

  // Stations: the axial positions of the face nodes, matched in pairs across.
  std::vector<std::pair<double, int>> face_nodes; // (s, node), sign of c in the node's c
  for (int i : skin)
  {
    const Vector r = body.reference_position(i) - origin_;
    if (std::abs(std::abs(r.dot(n_)) - c_max) <= tol)
      face_nodes.push_back({r.dot(a_), i});
  }
  std::sort(face_nodes.begin(), face_nodes.end());
  for (std::size_t j = 0; j < face_nodes.size();)
  {
    std::size_t e = j;
    int minus = -1, plus = -1;
    while (e < face_nodes.size() && face_nodes[e].first - face_nodes[j].first <= tol)
    {
      const int i = face_nodes[e].second;
      ((body.reference_position(i) - origin_).dot(n_) < 0 ? minus : plus) = i;
      ++e;
    }
    if (minus < 0 || plus < 0)
      throw InputError("large-rotation skin", "the two long faces have no matching node at s = " +
                                                  std::to_string(face_nodes[j].first) +
                                                  " m (needs a structured mesh)");
    s_.push_back(face_nodes[j].first);
    minus_.push_back(minus);
    plus_.push_back(plus);
    j = e;
  }
  auto station_of = [&](const Vector& x)
  {
    const double s = (x - origin_).dot(a_);
    const auto k = std::lower_bound(s_.begin(), s_.end(), s - tol) - s_.begin();
    if (k >= long(s_.size()) || std::abs(s_[k] - s) > tol)
      throw InputError("large-rotation skin",
                       "a skin node at s = " + std::to_string(s) + " m lies between face stations");
    return int(k);
  };
  for (int i : skin)
  {
    station_.push_back(station_of(body.reference_position(i)));
    c_.push_back((body.reference_position(i) - origin_).dot(n_));
  }
  for (int i : body.node_set(tip_set))
  {
    tip_station_.push_back(station_of(body.reference_position(i)));
    tip_c_.push_back((body.reference_position(i) - origin_).dot(n_));
  }
  theta_.resize(s_.size());
  theta_dot_.resize(s_.size());
  centre_.resize(s_.size());
}

void LargeRotationBeamSkin::update_rotations() const
{
  const auto& A = body_.rotation();
  for (std::size_t k = 0; k < s_.size(); ++k)
  {
    // Axial displacement and velocity of the two face nodes, in frame axes.
    const double um = (A.transpose() * body_.node_displacement(minus_[k])).dot(a_);
    const double up = (A.transpose() * body_.node_displacement(plus_[k])).dot(a_);
    const double vm = (A.transpose() * body_.node_velocity(minus_[k])).dot(a_);
    const double vp = (A.transpose() * body_.node_velocity(plus_[k])).dot(a_);
    theta_[k] = (um - up) / thickness_;
    theta_dot_[k] = (vm - vp) / thickness_;
  }
  centre_[0] = origin_ + s_[0] * a_;
  for (std::size_t k = 1; k < s_.size(); ++k)
  {
    const double h = s_[k] - s_[k - 1];
    auto t = [&](double th) { return Vector(a_ * std::cos(th) + n_ * std::sin(th)); };
    centre_[k] = centre_[k - 1] + 0.5 * h * (t(theta_[k - 1]) + t(theta_[k]));
  }
}

LargeRotationBeamSkin::Vector LargeRotationBeamSkin::place(int k, double c) const
{
  const double th = theta_[k];
  return centre_[k] + c * (n_ * std::cos(th) - a_ * std::sin(th));
}

void LargeRotationBeamSkin::skin_positions(std::vector<Vector>& x) const
{
  update_rotations();
  x.resize(station_.size());
  for (std::size_t i = 0; i < station_.size(); ++i)
    x[i] = body_.position() + body_.rotation() * place(station_[i], c_[i]);
}

void LargeRotationBeamSkin::skin_velocities(std::vector<Vector>& v) const
{
  update_rotations();
  auto normal = [&](double th) { return Vector(n_ * std::cos(th) - a_ * std::sin(th)); };
  auto tangent = [&](double th) { return Vector(a_ * std::cos(th) + n_ * std::sin(th)); };
  // Velocity of the centre line: dX_k/dt = sum_{l<k} h_l (n_l theta'_l + n_{l+1} theta'_{l+1}) / 2.
  std::vector<Vector> centre_velocity(s_.size(), Vector::Zero());
  for (std::size_t k = 1; k < s_.size(); ++k)
  {
    const double h = s_[k] - s_[k - 1];
    centre_velocity[k] =
        centre_velocity[k - 1] +
        0.5 * h * (normal(theta_[k - 1]) * theta_dot_[k - 1] + normal(theta_[k]) * theta_dot_[k]);
  }
  v.resize(station_.size());
  for (std::size_t i = 0; i < station_.size(); ++i)
  {
    const int k = station_[i];
    v[i] = body_.rotation() * (centre_velocity[k] - c_[i] * tangent(theta_[k]) * theta_dot_[k]);
  }
}

void LargeRotationBeamSkin::set_skin_forces(const std::vector<Vector>& f)
{
  update_rotations();
  const std::size_t m = s_.size();
  auto normal = [&](double th) { return Vector(n_ * std::cos(th) - a_ * std::sin(th)); };
  auto tangent = [&](double th) { return Vector(a_ * std::cos(th) + n_ * std::sin(th)); };
  // J^T f: per station, the force sum F_k and the couple of the offsets c_i.
  std::vector<Vector> F(m, Vector::Zero());
  std::vector<double> couple(m, 0.0);
  for (std::size_t i = 0; i < station_.size(); ++i)
  {
    const Vector fi = body_.rotation().transpose() * f[i]; // frame axes
    F[station_[i]] += fi;
    couple[station_[i]] -= c_[i] * fi.dot(tangent(theta_[station_[i]]));
  }
  std::vector<Vector> suffix(m + 1, Vector::Zero()); // suffix[l] = sum_{k >= l} F_k
  for (std::size_t l = m; l-- > 0;)
    suffix[l] = suffix[l + 1] + F[l];
  std::vector<int> nodes;
  std::vector<Vector> forces;
  for (std::size_t l = 0; l < m; ++l)
  {
    double weight_ahead = l + 1 < m ? 0.5 * (s_[l + 1] - s_[l]) : 0.0;
    double weight_behind = l > 0 ? 0.5 * (s_[l] - s_[l - 1]) : 0.0;
    const double M =
        normal(theta_[l]).dot(weight_ahead * suffix[l + 1] + weight_behind * suffix[l]) + couple[l];
    // theta_l = (u_a(minus) - u_a(plus)) / t: the conjugate forces are +-M/t along a.
    nodes.push_back(minus_[l]);
    forces.push_back(body_.rotation() * (a_ * (M / thickness_)));
    nodes.push_back(plus_[l]);
    forces.push_back(body_.rotation() * (-a_ * (M / thickness_)));
  }
  body_.set_node_forces(nodes, forces);
}

LargeRotationBeamSkin::Vector LargeRotationBeamSkin::tip_position() const
{
  update_rotations();
  Vector sum = Vector::Zero();
  for (std::size_t i = 0; i < tip_station_.size(); ++i)
    sum += place(tip_station_[i], tip_c_[i]);
  return body_.position() + body_.rotation() * (sum / double(tip_station_.size()));
}
} // namespace chipflex::coupling
