#pragma once
// The variables of a chipflex body FMU, derived from the body file alone, so the exporter
// (which writes modelDescription.xml) and the FMU's library (which answers fmi2Get/Set)
// agree on every name and value reference without reading the XML. Value references
// are the variables' positions in this list (0, 1, 2, ...), unique over all types.
// docs/export_fmu_sid.md lists the variables; all vectors are in world axes except the
// angular velocity (body frame), as in mbs::FloatingFrameBody.

#include "common/reduced_body_file.h"

#include <string>
#include <vector>

namespace chipflex::fmu
{
/// What a variable stands for; `index` and `component` say which one of a kind.
enum class Role
{
  // parameters (fixed after initialisation)
  clamped,                ///< Boolean: frame fixed to ground at its initial pose
  step_size,              ///< largest internal step, s
  rho_infinity,           ///< generalised-alpha spectral radius at infinite frequency
  damping,                ///< Integer: 0 none, 1 Rayleigh, 2 modal
  rayleigh_alpha,         ///< 1/s
  rayleigh_beta,          ///< s
  modal_damping_ratio,    ///< -
  gravity,                ///< component
  initial_position,       ///< component
  initial_rotation,       ///< 2D: angle (component 0); 3D: rotation vector component
                          // inputs (held over a communication step)
  frame_force,            ///< component
  frame_moment,           ///< component (2D: one, about z)
  set_force,              ///< index = node set number (alphabetical), component; shared equally
  skin_force,             ///< index = skin node number, component
                          // outputs
  frame_position,         ///< component
  frame_orientation,      ///< 2D: angle; 3D: quaternion w, x, y, z
  frame_velocity,         ///< component
  frame_angular_velocity, ///< component (body frame; 2D: one)
  modal_coordinate,       ///< index = mode
  modal_velocity,         ///< index = mode
  skin_position,          ///< index = skin node number, component
  skin_velocity,          ///< index = skin node number, component
  set_position,           ///< index = node set number, component: mean of the set's nodes
  linear_momentum,        ///< component
  kinetic_energy,
  strain_energy,
  // constants (Integer outputs): the skin's geometry for an importer that couples it
  skin_node_id, ///< index = skin node number: the body file's node id
  skin_face     ///< index = face, component = corner: skin node numbers
};

enum class VariableType
{
  real,
  integer,
  boolean
};

enum class Causality
{
  parameter,
  input,
  output
};

struct Variable
{
  std::string name, description, unit;
  VariableType type = VariableType::real;
  Causality causality = Causality::output;
  bool constant = false; ///< variability "constant" (else fixed / continuous / discrete)
  double start = 0;      ///< parameters, inputs and constants
  Role role = Role::clamped;
  int index = 0, component = 0;
};

class BodyVariables
{
public:
  explicit BodyVariables(const ReducedBodyData& body);

  const std::vector<Variable>& variables() const { return variables_; }
  const Variable& operator[](unsigned int vr) const { return variables_[vr]; }
  std::size_t size() const { return variables_.size(); }
  /// Names of the node sets in set_force's index order.
  const std::vector<std::string>& set_names() const { return set_names_; }
  /// Value reference of the first variable of a role (-1: none).
  int first(Role role) const;

private:
  void add(Variable v);

  std::vector<Variable> variables_;
  std::vector<std::string> set_names_;
};

/// The FMI GUID of a body FMU: "{8-4-4-4-12 hex digits}" from two FNV-1a 64-bit hashes
/// of the body file's bytes (so one body file always gives the same GUID).
std::string body_guid(const std::string& body_file_bytes);
} // namespace chipflex::fmu
