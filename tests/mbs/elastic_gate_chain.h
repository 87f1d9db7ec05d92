#pragma once
// The elastic gate's rigid-chain models (Antoci, Gallati & Sibilla 2007, Table 2): a
// 79 mm x 5 mm rubber gate (1100 kg/m^3) as 1, 2 or 3 equal links, torsion springs of
// 3.95, 3.95 and 2.633 Nm/rad per metre of depth. The same values are in
// cases/elastic_gate/chain*.prm.

#include "mbs/rigid_chain.h"

#include <stdexcept>

namespace chipflex::mbs::testing
{
inline RigidChainSpec elastic_gate_chain(int n_links)
{
  if (n_links < 1 || n_links > 3)
    throw std::invalid_argument("Table 2 has 1, 2 or 3 links");
  RigidChainSpec c;
  c.n_links = n_links;
  c.total_length = 0.079;
  c.thickness = 0.005;
  c.density = 1100;
  c.spring_rate = n_links == 3 ? 2.633 : 3.95;
  return c;
}
} // namespace chipflex::mbs::testing
