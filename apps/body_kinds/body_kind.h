#pragma once
// Body kinds of a case file's `subsection bodies`. Each kind is one file in this folder
// (rigid_kind.cc, flexible_kind.cc, ...) that declares its own keys and builds its body;
// it registers itself at start-up with a static BodyKindRegistration, so adding a kind
// touches no other file. The keys every body has (kind, name, how the fluid sees the
// skin, placement, initial velocities, the body integrator) are read once, in
// apps/body_case_keys.cc, and handed to the kind as a BodyContext.

#include "coupling/coupled_body.h"
#include "mbs/multibody_system.h"
#include "sph/wall_surface.h"

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
class ParameterHandler;
}

namespace chipflex::mbs
{
template <int dim>
class FloatingFrameBody;
}

namespace chipflex::apps
{
/// Where and how a body starts, in world coordinates (SI).
template <int dim>
struct BodyPlacement
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  Vector position = Vector::Zero();          ///< where the body's frame origin goes
  Eigen::Matrix<double, dim, dim> rotation = ///< of the frame (axis and angle)
      Eigen::Matrix<double, dim, dim>::Identity();
  Vector velocity = Vector::Zero();                           ///< of the frame origin
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero(); ///< world; 2D: z only
  bool clamped = true;                                        ///< fixed to the ground
};

/// What every kind gets besides its own keys.
template <int dim>
struct BodyContext
{
  std::string name;  ///< the body's name in outputs
  std::string where; ///< "CASE: bodies, body N", for error messages
  std::string case_path;
  BodyPlacement<dim> placement;
  Eigen::Matrix<double, dim, 1> gravity = Eigen::Matrix<double, dim, 1>::Zero();
  RotatingFrame rotating_frame; ///< the case's frame (the fluid's): fictitious forces
  double particle_spacing = 0;  ///< the fluid's dp, m (default skin spacing)
  mbs::IntegratorOptions integrator;
  double max_step = 0; ///< body sub-step limit, s (0: one per fluid step)
};

/// Declares a kind's keys inside `subsection body N`. Kinds may share a key (the same
/// quantity: `density`, `body file`); it is declared once, and must then have the same
/// default in every kind that declares it.
class BodyKeyDeclarations
{
public:
  BodyKeyDeclarations(dealii::ParameterHandler& prm, const std::string& kind,
                      std::vector<std::pair<std::string, std::string>>* declared);
  /// pattern: "double", "double >= 0", "integer >= N", "bool", "text", or "a|b|c".
  void declare(const std::string& key, const std::string& default_value, const std::string& pattern,
               const std::string& documentation);

private:
  dealii::ParameterHandler& prm_;
  std::string kind_;
  std::vector<std::pair<std::string, std::string>>* declared_; ///< (key, default)
};

/// Reads the keys of one `subsection body N` (the handler positioned inside it). Every
/// error names the case file, the body and the key.
class BodyKeys
{
public:
  BodyKeys(dealii::ParameterHandler& prm, std::string where, std::string case_path);
  std::string text(const std::string& key) const;
  double number(const std::string& key) const;
  double positive(const std::string& key) const;
  int integer(const std::string& key) const;
  bool flag(const std::string& key) const;
  /// Comma-separated numbers; `count` > 0 requires exactly that many.
  std::vector<double> numbers(const std::string& key, int count = 0) const;
  template <int dim>
  Eigen::Matrix<double, dim, 1> vector(const std::string& key) const;
  /// A file name looked up beside the case file first, then in the working directory.
  std::string file(const std::string& key) const;
  const std::string& where() const { return where_; }
  /// "CASE: bodies, body N, key".
  std::string at(const std::string& key) const { return where_ + ", " + key; }

private:
  dealii::ParameterHandler& prm_;
  std::string where_, case_path_;
};

class BodyKind
{
public:
  virtual ~BodyKind() = default;
  /// The value of `kind` that selects it, e.g. "rigid".
  virtual std::string name() const = 0;
  /// One line for the documentation of `kind`.
  virtual std::string description() const = 0;
  virtual void declare(BodyKeyDeclarations& keys) const = 0;
  virtual std::unique_ptr<coupling::CoupledBody<2>> build(const BodyKeys& keys,
                                                          const BodyContext<2>& context) const = 0;
  virtual std::unique_ptr<coupling::CoupledBody<3>> build(const BodyKeys& keys,
                                                          const BodyContext<3>& context) const = 0;
};

/// A kind that builds in 2D and 3D from one member template of `Kind`:
///   template <int dim> static std::unique_ptr<coupling::CoupledBody<dim>>
///   make(const BodyKeys&, const BodyContext<dim>&);
template <class Kind>
class AnyDimensionKind : public BodyKind
{
public:
  std::unique_ptr<coupling::CoupledBody<2>> build(const BodyKeys& keys,
                                                  const BodyContext<2>& context) const override
  {
    return Kind::template make<2>(keys, context);
  }
  std::unique_ptr<coupling::CoupledBody<3>> build(const BodyKeys& keys,
                                                  const BodyContext<3>& context) const override
  {
    return Kind::template make<3>(keys, context);
  }
};

/// Every registered kind, in the order of their names.
std::vector<const BodyKind*> body_kinds();
/// The kind called `name`; InputError at `where` listing the kinds otherwise.
const BodyKind& body_kind(const std::string& name, const std::string& where);

/// A static object of this type in a kind's file registers the kind.
struct BodyKindRegistration
{
  explicit BodyKindRegistration(std::unique_ptr<BodyKind> kind);
};

// ---- shared by the kinds built on mbs/ ----------------------------------------------
/// A MultibodySystem with the context's integrator and gravity.
template <int dim>
std::unique_ptr<mbs::MultibodySystem<dim>> make_body_system(const BodyContext<dim>& context);
/// Pose and velocities of the placement; clamps to ground if asked.
template <int dim>
void place_body(mbs::FloatingFrameBody<dim>& body, const BodyPlacement<dim>& placement);
/// InputError at `where` for kinds that exist in one dimension only.
[[noreturn]] void only_in_2d(const std::string& kind, const std::string& where);
/// InputError at `where` for kinds that do not take the fictitious forces of a turning
/// frame (`subsection rotating frame`) yet, when the case's frame turns.
void refuse_rotating_frame(const std::string& kind, const std::string& where,
                           const RotatingFrame& frame);
} // namespace chipflex::apps
