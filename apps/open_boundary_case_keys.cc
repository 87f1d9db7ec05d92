// `subsection open boundaries` of a case file (apps/case_file.h): the inlet and the outlet
// (sph/open_boundary.h, docs/sph.md "Open boundaries") and the checks of an internal flow.

#include "apps/open_boundary_case_keys.h"

#include "apps/case_values.h"
#include "common/input_error.h"

#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <sstream>

namespace chipflex::apps
{
using dealii::ParameterHandler;
using dealii::Patterns::Anything;
using dealii::Patterns::Bool;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;

void declare_open_boundary_keys(ParameterHandler& prm)
{
  // Open boundaries (sph/open_boundary.h, docs/sph.md "Open boundaries").
  prm.enter_subsection("open boundaries");
  prm.declare_entry("tear warning fraction", "0.05", Double(0),
                    "An internal flow holds its volume: when the fluid particles in the domain "
                    "fall more than this fraction below their number at the start (the "
                    "outlets taking out more than the inlets bring, a void opening), the run "
                    "says so in the log and in summary.txt (`continuity:` line, torn=yes). "
                    ">= 1: off (a tank that drains on purpose).");
  prm.declare_entry("watched frequencies", "", Anything(),
                    "Frequencies the case is meant to resolve (a forcing, a vortex shedding, an "
                    "expected body response), Hz, comma-separated. `chipflex run` warns when "
                    "the channel's acoustic frequency c0 / (4 L) lies within a factor of 3 of "
                    "one of them or of a flexible body's first natural frequency (docs/sph.md, "
                    "\"Choosing c0 for channels\").");
  for (const char* zone : {"inlet", "outlet"})
  {
    const bool inlet = std::string(zone) == "inlet";
    prm.enter_subsection(zone);
    prm.declare_entry("enabled", "false", Bool(),
                      inlet ? "A velocity inlet: buffer particles at a prescribed velocity, "
                              "density extrapolated from the fluid; new particles enter the "
                              "fluid as buffer particles cross the plane."
                            : "A pressure outlet: buffer particles at a prescribed pressure, "
                              "velocity extrapolated from the fluid; particles leaving the "
                              "buffer's far face are removed (outflow_particles).");
    prm.declare_entry("box min", "", Anything(),
                      "The buffer box's min corner, m (dim components). Its face on the fluid "
                      "side is the boundary plane; across the flow it spans the section.");
    prm.declare_entry("box max", "", Anything(), "The buffer box's max corner, m.");
    prm.declare_entry("direction", "+x", Selection("+x|-x|+y|-y|+z|-z"),
                      "The flow direction through the boundary (an inlet's points into the "
                      "fluid, an outlet's out of it).");
    prm.declare_entry("layers", "4", Integer(1),
                      "Buffer layers: the box's depth along the flow is layers * dp (at least "
                      "the kernel support 2h; DualSPHysics' default is 4), -.");
    if (inlet)
    {
      prm.declare_entry("velocity", "0", Double(0),
                        "Mean normal speed over the section, m/s (give this or flow rate).");
      prm.declare_entry("flow rate", "0", Double(0),
                        "Volume flow rate, m^3/s (2D: m^2/s per metre depth); the mean speed "
                        "is flow rate / the section the buffer's fluid fills (uniform profile; "
                        "parabolic: the box's section).");
      prm.declare_entry("profile", "uniform", Selection("uniform|parabolic"),
                        "uniform, or parabolic across the section: 2D 1.5 U (1 - eta^2) (plane "
                        "Poiseuille), 3D 2.25 U (1 - eta1^2)(1 - eta2^2), eta in [-1, 1].");
      prm.declare_entry("ramp time", "0", Double(0),
                        "The speed rises as (1 - cos(pi t/T))/2 over [0, T], s; 0: at once.");
    }
    else
      prm.declare_entry("pressure", "0", Double(),
                        "Pressure at the centre of the section, Pa (gauge; hydrostatic "
                        "across the section with gravity).");
    prm.leave_subsection();
  }
  prm.leave_subsection();
}

template <int dim>
void read_open_boundary_keys(ParameterHandler& prm, sph::CaseDescription<dim>& c)
{
  const auto& f = c.fluid;
  prm.enter_subsection("open boundaries");
  for (const char* name : {"inlet", "outlet"})
  {
    prm.enter_subsection(name);
    const std::string where = std::string("open boundaries/") + name;
    if (prm.get_bool("enabled"))
    {
      sph::OpenBoundary<dim> z;
      z.name = name;
      z.kind = z.name == "inlet" ? sph::OpenBoundaryKind::inlet : sph::OpenBoundaryKind::outlet;
      const std::string direction = prm.get("direction");
      z.sign = direction[0] == '+' ? 1 : -1;
      z.axis = direction[1] - 'x';
      if (z.axis >= dim)
        throw InputError(where + "/direction", "'" + direction + "' in a 2D case");
      z.box_min = vector_of<dim>(where + "/box min", prm.get("box min"));
      z.box_max = vector_of<dim>(where + "/box max", prm.get("box max"));
      if (!((z.box_max - z.box_min).minCoeff() > 0))
        throw InputError(where + "/box max", "must exceed the box min corner in every component");
      // The box's extent along the flow is its plane face and `layers` spacings behind it.
      const double depth = prm.get_integer("layers") * f.particle_spacing;
      const double plane = z.plane();
      const bool upper = (z.kind == sph::OpenBoundaryKind::inlet) == (z.sign > 0);
      if (std::abs(z.thickness() - depth) > 1e-6 * depth)
      {
        std::ostringstream s;
        s << "the box is " << z.thickness() << " m deep along " << direction
          << ", layers * dp = " << depth << " m: make them agree";
        throw InputError(where + "/layers", s.str());
      }
      if (upper)
        z.box_min[z.axis] = plane - depth;
      else
        z.box_max[z.axis] = plane + depth;
      if (z.kind == sph::OpenBoundaryKind::inlet)
      {
        const double u = prm.get_double("velocity"), q = prm.get_double("flow rate");
        if ((u > 0) == (q > 0))
          throw InputError(where, "give exactly one of velocity and flow rate (positive)");
        z.velocity = u > 0 ? u : q / z.section_area(); // the fluid's section: case_setup.cc
        z.flow_rate = u > 0 ? 0 : q;
        z.profile = prm.get("profile") == "parabolic" ? sph::InletProfile::parabolic
                                                      : sph::InletProfile::uniform;
        z.ramp_time = prm.get_double("ramp time");
      }
      else
        z.pressure = prm.get_double("pressure");
      c.open_boundaries.push_back(z);
    }
    prm.leave_subsection();
  }
  prm.leave_subsection();

  // An internal flow (an inlet or an outlet) is shifted unless the case says otherwise.
}

template void read_open_boundary_keys(ParameterHandler&, sph::CaseDescription<2>&);
template void read_open_boundary_keys(ParameterHandler&, sph::CaseDescription<3>&);
} // namespace chipflex::apps
