#include "apps/simulation_factory.h"

#include "apps/body_case_keys.h"
#include "apps/contact_case_keys.h"
#include "apps/coupled_simulation.h"
#include "apps/fluid_simulation.h"
#include "common/input_error.h"

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
  // Over MPI every rank steps its own copy of each body: the fe kind's serial deal.II
  // solver (MPI_COMM_SELF) and an FMU (unpacked into a folder of each process's own) give
  // every rank the same numbers. An SPH solid keeps particles of its own, which are not
  // spread over the ranks.
  if (distributed)
    for (const auto& b : bodies.bodies)
      if (b.kind == "sph solid")
        throw InputError(c.path + ": bodies, " + b.name,
                         "the " + b.kind +
                             " kind does not run over MPI yet (the others do); run one process "
                             "with --threads N");
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
