#pragma once
// The `fmu` body kind: a body given as an FMI 2.0 co-simulation FMU, coupled through its
// skin like a `flexible` body. Any FMU with the skin variables of docs/export_fmu_sid.md
// will do (chipflex's own `chipflex export fmu` ones, or another tool's):
//   required  skin.position[i].x|y, skin.velocity[i].x|y (outputs, Real),
//             skin.force[i].x|y (inputs, Real), skin.face[f][0|1] (Integer constants:
//             skin node numbers, outward normal as for every skin)
//   optional  set.<probe set>.position.x|y (the probe; else the mean of the skin),
//             linear_momentum.x|y, and the parameters clamped, step_size, rho_infinity,
//             damping, rayleigh_alpha, rayleigh_beta, modal_damping_ratio, gravity.x|y,
//             initial.position.x|y, initial.angle, set from the case where present.
// The FMU is unpacked into a temporary folder, its library loaded with dlopen (its own
// symbols stay its own), and driven by the co-simulation calling sequence: per fluid
// step, skin forces in (fmi2SetReal), one fmi2DoStep over the step, positions and
// velocities out. Checkpoints use fmi2SerializeFMUstate.

#include "coupling/coupled_body.h"

#include <Eigen/Core>
#include <memory>
#include <string>

namespace chipflex::coupling
{
/// What the case sets of an FMU body (the FMU's parameters where it has them).
struct FmuBodySettings
{
  std::string name = "body";
  std::string fmu_file;
  bool clamped = true;
  Eigen::Vector2d position = Eigen::Vector2d::Zero(); ///< initial frame position, m
  double angle = 0;                                   ///< initial frame rotation, rad
  bool implicit = true;                               ///< refused if false (it integrates itself)
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero(); ///< refused if non-zero (starts at rest)
  double rho_infinity = 0.9;
  double max_step = 0; ///< the FMU's internal step limit, s (0: one per fluid step)
  double modal_damping = 0, rayleigh_mass = 0, rayleigh_stiffness = 0;
  std::string probe_set = "tip";
};

/// Loads the FMU of `settings.fmu_file`; InputError naming the file for an FMU that is
/// not FMI 2.0 co-simulation, lacks the skin variables or fails to instantiate.
std::unique_ptr<CoupledBody<2>> make_fmu_body(const FmuBodySettings& settings,
                                              const Eigen::Vector2d& gravity);
} // namespace chipflex::coupling
