#include "coupling/chip_source.h"

#include "common/input_error.h"

#include <cmath>

namespace chipflex::coupling
{
template <int dim>
ChipSource<dim>::ChipSource(CoSimulation<dim>& cosim, const ChipSourceSettings<dim>& settings)
    : cosim_(cosim), settings_(settings)
{
  if (settings_.pool.empty())
    throw InputError("chip source, bodies", "names no body");
  if (!(settings_.interval > 0))
    throw InputError("chip source, interval", "must be positive");
  if (!(settings_.exit_normal.norm() > 0))
    throw InputError("chip source, exit normal", "must not be the zero vector");
  settings_.exit_normal.normalize();
  for (int b : settings_.pool)
  {
    if (b < 0 || b >= cosim_.n_bodies())
      throw InputError("chip source, bodies", "names a body that is not in the run");
    parking_.push_back(cosim_.body(b).state());
    cosim_.set_parked(b, true);
  }
  chip_.assign(settings_.pool.size(), 0);
  for (int b : settings_.pool)
  {
    const Vector centre = skin_centre(b); // fills nodes_
    for (const Vector& x : nodes_)
      clearance_ = std::max(clearance_, (x - centre).norm());
  }
  // Where a released chip's skin centre starts: the first pool body put at the release
  // pose for a moment, then back into its parking state.
  {
    const int b = settings_.pool.front();
    cosim_.body(b).place(0, settings_.position, settings_.rotation, settings_.velocity,
                         settings_.angular_velocity);
    release_centre_ = skin_centre(b);
    cosim_.body(b).restore(parking_.front());
  }
  cosim_.fluid().add_hook(sph::HookPoint::after_step,
                          [this](sph::FluidSolver<dim>& f) { after_step(f.time()); });
}

template <int dim>
typename ChipSource<dim>::Vector ChipSource<dim>::skin_centre(int body) const
{
  cosim_.body(body).skin().skin_positions(nodes_);
  Vector c = Vector::Zero();
  for (const Vector& x : nodes_)
    c += x;
  return c / double(std::max<std::size_t>(1, nodes_.size()));
}

template <int dim>
bool ChipSource<dim>::edge_occupied() const
{
  for (std::size_t k = 0; k < settings_.pool.size(); ++k)
    if (chip_[k] != 0 && (skin_centre(settings_.pool[k]) - release_centre_).norm() < clearance_)
      return true;
  return false;
}

template <int dim>
void ChipSource<dim>::after_step(double t)
{
  const auto& s = settings_;
  // Chips that have left the segment go back to their parking state.
  for (std::size_t k = 0; k < s.pool.size(); ++k)
  {
    const int b = s.pool[k];
    if (chip_[k] == 0 || s.exit_normal.dot(skin_centre(b) - s.exit_point) <= 0)
      continue;
    cosim_.body(b).restore(parking_[k]);
    cosim_.set_parked(b, true);
    chip_[k] = 0;
    ++removed_;
  }
  // Releases due by t, each into the first parked body of the pool.
  while (t >= s.first_release + double(due_) * s.interval)
  {
    if (edge_occupied())
    {
      delayed_ += waiting_ ? 0 : 1;
      waiting_ = true;
      break;
    }
    waiting_ = false;
    ++due_;
    std::size_t k = 0;
    while (k < s.pool.size() && chip_[k] != 0)
      ++k;
    if (k == s.pool.size())
    {
      ++skipped_;
      continue;
    }
    const int b = s.pool[k];
    cosim_.body(b).place(t, s.position, s.rotation, s.velocity, s.angular_velocity);
    cosim_.set_parked(b, false);
    chip_[k] = ++released_;
  }
}

template <int dim>
std::vector<double> ChipSource<dim>::state() const
{
  std::vector<double> out = {double(released_), double(removed_), double(skipped_), double(due_)};
  for (long c : chip_)
    out.push_back(double(c));
  out.push_back(double(delayed_));
  out.push_back(waiting_ ? 1.0 : 0.0);
  return out;
}

template <int dim>
void ChipSource<dim>::restore(const std::vector<double>& state)
{
  // A checkpoint written before the wait at the edge lacks its last two values.
  const std::size_t n = 4 + chip_.size();
  if (state.size() != n && state.size() != n + 2)
    throw InputError("chip source checkpoint", "holds " + std::to_string(state.size()) +
                                                   " values, this run's pool needs " +
                                                   std::to_string(n + 2));
  released_ = long(state[0]);
  removed_ = long(state[1]);
  skipped_ = long(state[2]);
  due_ = long(state[3]);
  for (std::size_t k = 0; k < chip_.size(); ++k)
  {
    chip_[k] = long(state[4 + k]);
    cosim_.set_parked(settings_.pool[k], chip_[k] == 0);
  }
  delayed_ = state.size() == n + 2 ? long(state[n]) : 0;
  waiting_ = state.size() == n + 2 && state[n + 1] != 0;
}

template class ChipSource<2>;
template class ChipSource<3>;
} // namespace chipflex::coupling
