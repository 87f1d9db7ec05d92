#pragma once
// `subsection probes` of a `chipflex run` case file (apps/case_file.h).

#include "apps/jam_watch.h"
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

/// `probes/jam watch`; its gauges must be among the case's (InputError otherwise).
template <int dim>
JamWatchSettings read_jam_watch_keys(dealii::ParameterHandler& prm,
                                     const sph::CaseDescription<dim>& c);
} // namespace chipflex::apps
