#include "apps/simulation_factory.h"

#include "apps/body_case_keys.h"
#include "apps/contact_case_keys.h"
#include "apps/coupled_simulation.h"
#include "apps/fluid_simulation.h"

namespace chipflex::apps
{
std::unique_ptr<Simulation> make_simulation(const CaseFile& c, const std::string& dir,
                                            bool distributed)
{
  if (n_case_bodies(*c.parameters, c.body_subsections) > 0)
  {
    const ContactCase contact = read_contact_case(*c.parameters, c.path);
    if (c.dimension == 2)
      return std::make_unique<CoupledSimulation<2>>(
          c.case_2d, read_body_case<2>(*c.parameters, c.path, c.case_2d, c.body_subsections), dir,
          contact, distributed);
    return std::make_unique<CoupledSimulation<3>>(
        c.case_3d, read_body_case<3>(*c.parameters, c.path, c.case_3d, c.body_subsections), dir,
        contact, distributed);
  }
  if (c.dimension == 2)
    return std::make_unique<FluidSimulation<2>>(c.case_2d, dir, distributed);
  return std::make_unique<FluidSimulation<3>>(c.case_3d, dir, distributed);
}
} // namespace chipflex::apps
