#pragma once
// `subsection contact` of a `chipflex run` case file: contact between the coupled bodies
// and with the walls (the tank, `geometry/walls` polylines, permeable barriers), see
// docs/contact.md. Every key is declared once here with its unit and default.

#include "coupling/contact.h"

#include <string>
#include <vector>

namespace dealii
{
class ParameterHandler;
}

namespace chipflex::apps
{
struct ContactCase
{
  bool enabled = false;
  coupling::ContactParameters parameters;
  /// The axis about which every wall's contact torque is probed: a point and, in 3D, a
  /// direction (x, y, z, ax, ay, az; 2D: x, y, about z), m.
  std::vector<double> torque_axis;
};

void declare_contact_keys(dealii::ParameterHandler& prm);

/// Reads `subsection contact`; InputError for a value out of range, or for a permeable
/// barrier (`geometry/walls/fluid passes`) in a case without contact, which nothing
/// would feel.
ContactCase read_contact_case(dealii::ParameterHandler& prm, const std::string& case_path);
} // namespace chipflex::apps
