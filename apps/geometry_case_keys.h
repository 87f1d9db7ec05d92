#pragma once
// `subsection geometry` of a `chipflex run` case file (apps/case_file.h).

#include "sph/case_setup.h"

#include <string>

namespace dealii
{
class ParameterHandler;
}

namespace chipflex::apps
{
void declare_geometry_keys(dealii::ParameterHandler& prm);

/// Fills the fluid blocks, the domain, the initial velocity, the fluid region, the tank
/// and the extra walls; surface files are looked up beside `case_path`.
template <int dim>
void read_geometry_keys(dealii::ParameterHandler& prm, sph::CaseDescription<dim>& c,
                        const std::string& case_path);
} // namespace chipflex::apps
