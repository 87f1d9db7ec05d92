#include "apps/body_kinds/body_kind.h"

#include "apps/case_values.h"
#include "common/input_error.h"
#include "mbs/floating_frame_body.h"

#include <algorithm>
#include <deal.II/base/parameter_handler.h>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>

namespace chipflex::apps
{
using dealii::ParameterHandler;
namespace Patterns = dealii::Patterns;

BodyKeyDeclarations::BodyKeyDeclarations(ParameterHandler& prm, const std::string& kind,
                                         std::vector<std::pair<std::string, std::string>>* declared)
    : prm_(prm), kind_(kind), declared_(declared)
{
}

void BodyKeyDeclarations::declare(const std::string& key, const std::string& default_value,
                                  const std::string& pattern, const std::string& documentation)
{
  for (const auto& [name, value] : *declared_)
    if (name == key)
    {
      if (value != default_value)
        throw std::logic_error("body key '" + key + "' declared with two defaults ('" + value +
                               "', and '" + default_value + "' by kind " + kind_ + ")");
      return;
    }
  declared_->emplace_back(key, default_value);
  std::unique_ptr<Patterns::PatternBase> p;
  if (pattern == "double")
    p = std::make_unique<Patterns::Double>();
  else if (pattern == "double >= 0")
    p = std::make_unique<Patterns::Double>(0);
  else if (pattern.rfind("integer >= ", 0) == 0)
    p = std::make_unique<Patterns::Integer>(std::stoi(pattern.substr(11)));
  else if (pattern == "bool")
    p = std::make_unique<Patterns::Bool>();
  else if (pattern == "text")
    p = std::make_unique<Patterns::Anything>();
  else
    p = std::make_unique<Patterns::Selection>(pattern);
  prm_.declare_entry(key, default_value, *p, kind_ + ": " + documentation);
}

BodyKeys::BodyKeys(ParameterHandler& prm, std::string where, std::string case_path)
    : prm_(prm), where_(std::move(where)), case_path_(std::move(case_path))
{
}

std::string BodyKeys::text(const std::string& key) const
{
  return prm_.get(key);
}

double BodyKeys::number(const std::string& key) const
{
  // Keys without a default (a body's material) are declared as text with an empty
  // default, so the value is checked here rather than by a deal.II pattern.
  const std::string value = prm_.get(key);
  if (value.find_first_not_of(" \t") == std::string::npos)
    throw InputError(at(key), "required (no default: every body states its material)");
  std::size_t used = 0;
  double v = 0;
  try
  {
    v = std::stod(value, &used);
  }
  catch (const std::exception&)
  {
    used = 0;
  }
  if (used == 0 || value.find_first_not_of(" \t", used) != std::string::npos)
    throw InputError(at(key), "'" + value + "' is not a number");
  return v;
}

double BodyKeys::positive(const std::string& key) const
{
  const double v = number(key);
  if (!(v > 0))
    throw InputError(at(key), "must be positive, got " + prm_.get(key));
  return v;
}

int BodyKeys::integer(const std::string& key) const
{
  return int(prm_.get_integer(key));
}

bool BodyKeys::flag(const std::string& key) const
{
  return prm_.get_bool(key);
}

std::vector<double> BodyKeys::numbers(const std::string& key, int count) const
{
  const std::vector<double> v = apps::numbers(at(key), prm_.get(key));
  if (count > 0 && int(v.size()) != count)
    throw InputError(at(key), "'" + prm_.get(key) + "': expected " + std::to_string(count) +
                                  " numbers, got " + std::to_string(v.size()));
  return v;
}

template <int dim>
Eigen::Matrix<double, dim, 1> BodyKeys::vector(const std::string& key) const
{
  const auto v = numbers(key);
  if (v.empty())
    return Eigen::Matrix<double, dim, 1>::Zero();
  if (int(v.size()) != dim)
    throw InputError(at(key), "'" + prm_.get(key) + "': expected " + std::to_string(dim) +
                                  " numbers (a " + std::to_string(dim) + "D vector), got " +
                                  std::to_string(v.size()));
  return Eigen::Map<const Eigen::Matrix<double, dim, 1>>(v.data());
}
template Eigen::Matrix<double, 2, 1> BodyKeys::vector<2>(const std::string&) const;
template Eigen::Matrix<double, 3, 1> BodyKeys::vector<3>(const std::string&) const;

std::string BodyKeys::file(const std::string& key) const
{
  namespace fs = std::filesystem;
  const std::string name = prm_.get(key);
  if (name.empty())
    throw InputError(at(key), "no file given");
  if (fs::path(name).is_absolute())
    return name;
  const fs::path beside = fs::path(case_path_).parent_path() / name;
  if (fs::exists(beside))
    return beside.string();
  if (fs::exists(name))
    return name;
  throw InputError(at(key), "file '" + name + "' found neither beside " + case_path_ +
                                " nor in the working directory");
}

namespace
{
std::map<std::string, std::unique_ptr<BodyKind>>& registry()
{
  static std::map<std::string, std::unique_ptr<BodyKind>> kinds;
  return kinds;
}
} // namespace

BodyKindRegistration::BodyKindRegistration(std::unique_ptr<BodyKind> kind)
{
  const std::string name = kind->name();
  if (!registry().emplace(name, std::move(kind)).second)
    throw std::logic_error("body kind '" + name + "' registered twice");
}

std::vector<const BodyKind*> body_kinds()
{
  std::vector<const BodyKind*> out;
  for (const auto& [name, kind] : registry())
    out.push_back(kind.get());
  return out;
}

const BodyKind& body_kind(const std::string& name, const std::string& where)
{
  const auto it = registry().find(name);
  if (it != registry().end())
    return *it->second;
  std::string known;
  for (const auto& [n, kind] : registry())
    known += (known.empty() ? "" : ", ") + n;
  throw InputError(where, "unknown body kind '" + name + "' (expected " + known + ")");
}

template <int dim>
std::unique_ptr<mbs::MultibodySystem<dim>> make_body_system(const BodyContext<dim>& context)
{
  auto system = std::make_unique<mbs::MultibodySystem<dim>>(context.integrator);
  system->set_gravity(context.gravity);
  system->set_rotating_frame(context.rotating_frame);
  return system;
}

template <int dim>
void place_body(mbs::FloatingFrameBody<dim>& body, const BodyPlacement<dim>& p)
{
  body.set_pose(p.position, p.rotation);
  Eigen::Matrix<double, mbs::rotation_dofs<dim>, 1> omega;
  if constexpr (dim == 2)
    omega[0] = p.angular_velocity[2];
  else
    omega = p.rotation.transpose() * p.angular_velocity; // the body frame's
  body.set_frame_velocity(p.velocity, omega);
  if (p.clamped)
    body.clamp_to_ground();
}

void only_in_2d(const std::string& kind, const std::string& where)
{
  throw InputError(where + ", kind", "the " + kind + " kind exists in 2D cases only");
}

void refuse_rotating_frame(const std::string& kind, const std::string& where,
                           const RotatingFrame& frame)
{
  if (frame.active())
    throw InputError(where + ", kind",
                     "a body of kind " + kind +
                         " does not feel the turning frame's fictitious forces (rotating "
                         "frame/angular velocity); use kind rigid or flexible");
}

template std::unique_ptr<mbs::MultibodySystem<2>> make_body_system(const BodyContext<2>&);
template std::unique_ptr<mbs::MultibodySystem<3>> make_body_system(const BodyContext<3>&);
template void place_body(mbs::FloatingFrameBody<2>&, const BodyPlacement<2>&);
template void place_body(mbs::FloatingFrameBody<3>&, const BodyPlacement<3>&);
} // namespace chipflex::apps
