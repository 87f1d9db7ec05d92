#pragma once
// `subsection bodies` of a `chipflex run` case file: any number of coupled bodies, each
// in `subsection body N` (N = 1, 2, ...) with a `kind` from the registry
// (apps/body_kinds/). The keys every body has are declared and read here; each kind
// declares and reads its own. A key set for a body whose kind does not use it is an
// error, as is any bad value: InputError naming the case file, the body and the key.

#include "apps/chip_source_case_keys.h"
#include "coupling/coupled_body.h"
#include "sph/case_setup.h"
#include "sph/wall_surface.h"

#include <memory>
#include <string>
#include <vector>

namespace dealii
{
class ParameterHandler;
}

namespace chipflex::apps
{
/// A body built from the case, with how the fluid sees its skin.
template <int dim>
struct CaseBody
{
  std::string name;
  std::string kind;
  std::unique_ptr<coupling::CoupledBody<dim>> body;
  sph::WallModel wall_model = sph::WallModel::lennard_jones;
  /// `wall model = automatic`: thin skin or lennard jones, chosen from the skin's
  /// thickness when the fluid is known (CoupledSimulation).
  bool automatic_wall_model = false;
  std::string wall_model_note;               ///< why automatic chose what it chose (summary)
  sph::LennardJonesParameters lennard_jones; ///< zeros: derived from the fluid
  std::size_t displaced_fluid = 0;           ///< fluid particles removed from inside it
  int probe_node = -1; ///< skin node that is the probe (`probe point`); -1: the kind's own

  /// The probe point now: the chosen skin node, or the kind's probe point.
  Eigen::Matrix<double, dim, 1> probe_position() const
  {
    if (probe_node < 0)
      return body->probe_position();
    std::vector<Eigen::Matrix<double, dim, 1>> x;
    body->skin().skin_positions(x);
    return x[probe_node];
  }
};

/// What the case says about the coupled run.
template <int dim>
struct BodyCase
{
  std::vector<CaseBody<dim>> bodies;
  ChipSourceCase<dim> chip_source; ///< `bodies/chip source`; no bodies named: none
};

/// The highest N of a `subsection body N` in the case file's text (0: none), so that
/// that many body subsections can be declared before parsing.
int count_body_subsections(const std::string& case_text);

/// Declares `subsection bodies` with `n_bodies` body subsections (at least one).
void declare_body_keys(dealii::ParameterHandler& prm, int n_bodies);

/// Number of bodies the case declares (`count`, or up to the last body subsection with
/// a kind when 0); `declared`: the body subsections declared (count_body_subsections).
int n_case_bodies(dealii::ParameterHandler& prm, int declared);

/// Reads and builds the bodies; relative file names are looked up beside the case file
/// first, then in the working directory.
template <int dim>
BodyCase<dim> read_body_case(dealii::ParameterHandler& prm, const std::string& case_path,
                             const sph::CaseDescription<dim>& fluid, int declared);
} // namespace chipflex::apps
