#include "apps/fluid_continuity.h"

#include "common/hdf5_file.h"

#include <sstream>

namespace chipflex::apps
{
std::string FluidContinuityCheck::update(double time, std::size_t n_fluid)
{
  last_ = n_fluid;
  if (!started_)
  {
    started_ = true;
    start_ = smallest_ = n_fluid;
    smallest_time_ = time;
    return "";
  }
  if (n_fluid < smallest_)
  {
    smallest_ = n_fluid;
    smallest_time_ = time;
  }
  if (warned_ || warning_fraction_ >= 1 || drop(n_fluid) <= warning_fraction_)
    return "";
  warned_ = true;
  std::ostringstream s;
  s.precision(4);
  s << "warning: the fluid is tearing: " << n_fluid << " fluid particles at t = " << time << " s, "
    << 100 * drop(n_fluid) << " % fewer than the " << start_ << " at the start (limit "
    << 100 * warning_fraction_ << " %): the outlets take out more than the inlets bring";
  if (background_pressure_ > 0)
    s << ": a void is opening, or, under the background pressure of " << background_pressure_
      << " Pa, the particles are thinning evenly, which shifts the gauge pressures by about "
      << 2 * background_pressure_ * drop(n_fluid) << " Pa (docs/sph.md, \"Internal flows that "
      << "tear\", \"What the background pressure costs\")";
  else
    s << " and a void is opening (docs/sph.md, \"Internal flows that tear\")";
  return s.str();
}

std::string FluidContinuityCheck::summary_line() const
{
  std::ostringstream s;
  s.precision(6);
  s << "continuity: start_fluid_particles=" << start_ << " min_fluid_particles=" << smallest_
    << " min_at_t_s=" << smallest_time_ << " end_fluid_particles=" << last_
    << " largest_drop_percent=" << 100 * drop(smallest_) << " torn=" << (warned_ ? "yes" : "no");
  return s.str();
}

void FluidContinuityCheck::save(Hdf5File& file, const std::string& group) const
{
  file.write_attribute(group, "continuity_start", std::int64_t(start_));
  file.write_attribute(group, "continuity_smallest", std::int64_t(smallest_));
  file.write_attribute(group, "continuity_smallest_time", smallest_time_);
  file.write_attribute(group, "continuity_warned", std::int64_t(warned_));
}

void FluidContinuityCheck::load(const Hdf5File& file, const std::string& group)
{
  // Checkpoints written before the check existed: start afresh at the restart.
  if (!file.has_attribute(group, "continuity_start"))
    return;
  start_ = std::size_t(file.read_integer_attribute(group, "continuity_start"));
  smallest_ = std::size_t(file.read_integer_attribute(group, "continuity_smallest"));
  smallest_time_ = file.read_double_attribute(group, "continuity_smallest_time");
  warned_ = file.read_integer_attribute(group, "continuity_warned") != 0;
  started_ = true;
}
} // namespace chipflex::apps
