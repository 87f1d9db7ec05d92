#pragma once
// Builds the coupled body a BodyDescription declares, with its probe. Every kind comes
// out as a CoupledBody<2>, so the co-simulation loop never branches on the kind.
// Bad values throw InputError naming the body and the key.

#include "coupling/body_description.h"
#include "coupling/coupled_body.h"

#include <memory>

namespace chipflex::coupling
{
std::unique_ptr<CoupledBody<2>> make_coupled_body(const BodyDescription& description,
                                                  const Eigen::Vector2d& gravity);
} // namespace chipflex::coupling
