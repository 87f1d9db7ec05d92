#pragma once
// `subsection open boundaries` of a `chipflex run` case file (apps/case_file.h).

#include "sph/case_setup.h"

#include <string>

namespace dealii
{
class ParameterHandler;
}

namespace chipflex::apps
{
void declare_open_boundary_keys(dealii::ParameterHandler& prm);

/// Fills c.open_boundaries (the fluid's particle spacing must be read already: the
/// buffers' depth is layers * dp).
template <int dim>
void read_open_boundary_keys(dealii::ParameterHandler& prm, sph::CaseDescription<dim>& c);
} // namespace chipflex::apps
