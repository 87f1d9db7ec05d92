#pragma once
// `subsection probes` of a `chipflex run` case file (apps/case_file.h).

#include "sph/case_setup.h"

#include <string>

namespace dealii
{
class ParameterHandler;
}

namespace chipflex::apps
{
void declare_probe_keys(dealii::ParameterHandler& prm);

/// Fills the pressure, water-height and flow-rate gauges.
template <int dim>
void read_probe_keys(dealii::ParameterHandler& prm, sph::CaseDescription<dim>& c);
} // namespace chipflex::apps
