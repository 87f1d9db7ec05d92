#pragma once
// The Simulation a case file describes: the fluid alone, or fluid plus bodies when the
// case has `subsection bodies` (coupling/). Used by `chipflex run` and `chipflex bench case`.

#include "apps/case_file.h"
#include "apps/simulation.h"

#include <memory>
#include <string>

namespace chipflex::apps
{
/// Builds the simulation of case `c`, its outputs going to `dir`. `distributed`: spread
/// the fluid over the MPI ranks (bodies stay whole on every rank).
std::unique_ptr<Simulation> make_simulation(const CaseFile& c, const std::string& dir,
                                            bool distributed = false);
} // namespace chipflex::apps
