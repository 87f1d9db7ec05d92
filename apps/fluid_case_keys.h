#pragma once
// `subsection fluid`, `time` and `output` of a `chipflex run` case file (apps/case_file.h).

#include "sph/case_setup.h"

#include <string>

namespace dealii
{
class ParameterHandler;
}

namespace chipflex::apps
{
void declare_fluid_keys(dealii::ParameterHandler& prm);

/// Fills c.fluid, the sound coefficient, the hydrostatic start, the end time and the frame
/// interval; returns `fluid/particle shifting` (automatic, on or off: whether an automatic
/// case is shifted depends on its open boundaries, read later). c.fluid.shifting_coefficient
/// is the key's value unless shifting is off.
template <int dim>
std::string read_fluid_keys(dealii::ParameterHandler& prm, sph::CaseDescription<dim>& c);
} // namespace chipflex::apps
