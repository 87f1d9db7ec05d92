#include "apps/simulation_factory.h"

#include "apps/body_case_keys.h"
#include "apps/contact_case_keys.h"
#include "apps/coupled_simulation.h"
#include "apps/fluid_simulation.h"

namespace chipflex::apps
{
namespace
{
template <int dim>
std::unique_ptr<Simulation> make_coupled(const CaseFile& c, const sph::CaseDescription<dim>& fluid,
                                         const std::string& dir, bool distributed)
{
  const ContactCase contact = read_contact_case(*c.parameters, c.path);
  BodyCase<dim> bodies = read_body_case<dim>(*c.parameters, c.path, fluid, c.body_subsections);
  // Over MPI every rank steps its own copy of each body with the same numbers in the same
  // order, so the copies stay alike: the fe kind's serial deal.II solver (MPI_COMM_SELF),
  // an FMU (unpacked into a folder of each process's own) and an SPH solid's particles
  // (loaded through its skin, as every kind) included.
  return std::make_unique<CoupledSimulation<dim>>(fluid, std::move(bodies), dir, contact,
                                                  distributed);
}
} // namespace

std::unique_ptr<Simulation> make_simulation(const CaseFile& c, const std::string& dir,
                                            bool distributed)
{
  if (n_case_bodies(*c.parameters, c.body_subsections) > 0)
    return c.dimension == 2 ? make_coupled(c, c.case_2d, dir, distributed)
                            : make_coupled(c, c.case_3d, dir, distributed);
  if (c.dimension == 2)
    return std::make_unique<FluidSimulation<2>>(c.case_2d, dir, distributed);
  return std::make_unique<FluidSimulation<3>>(c.case_3d, dir, distributed);
}
} // namespace chipflex::apps
