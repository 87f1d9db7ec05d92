#pragma once
// A coupled body as plain data: what a case file's `subsection bodies` declares
// (apps/body_case_keys.cc reads it, tests fill it directly) and body_factory.h builds.
// 2D (per metre of depth); SI units.

#include "sph/solid_body.h"
#include "sph/wall_surface.h"

#include <Eigen/Core>
#include <string>

namespace chipflex::coupling
{
enum class BodyKind
{
  rigid,     ///< a rigid rectangle (box), free or fixed
  chain,     ///< the seed's rigid-link gate with torsion springs (Table 2)
  flexible,  ///< a reduced floating-frame body from `chipflex reduce`
  sph_solid, ///< an SPH-solid strip (Gray, Monaghan & Swift 2001; Table 1)
  fmu        ///< an FMI 2.0 co-simulation FMU with skin variables (coupling/fmu_body.h)
};

struct BodyDescription
{
  std::string name = "body";
  BodyKind kind = BodyKind::flexible;

  // ---- how the fluid sees the skin
  sph::WallModel wall_model = sph::WallModel::lennard_jones;
  sph::LennardJonesParameters lennard_jones; ///< zeros: derived from the fluid
  double expected_pressure = 0;              ///< Pa, for the derived k (0: rho0 (c0/10)^2)

  // ---- placement (world, m / rad)
  /// rigid: centre of the box; chain: clamp point (top hinge); flexible: where the body
  /// file's origin goes; sph solid: centre of the clamped end.
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  double angle = 0;    ///< rigid and flexible: frame rotation, rad
  bool clamped = true; ///< rigid: fixed in space; flexible: frame clamped to ground
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero(); ///< initial, free rigid/flexible bodies

  // ---- body integrator (mbs kinds)
  bool implicit = true;      ///< generalised-alpha; false: symplectic Euler
  double rho_infinity = 0.9; ///< generalised-alpha spectral radius
  double max_step = 0;       ///< body sub-step limit, s (0: one step per fluid step)

  // ---- rigid box
  double width = 0.05, height = 0.05; ///< m
  double density = 1100;              ///< kg/m^3 (also chain links)

  // ---- chain (Table 2 when spring_rate = 0)
  int links = 1;
  double length = 0.079, thickness = 0.005; ///< m (also the sph solid strip)
  double spring_rate = 0;                   ///< Nm/rad per metre; 0: the seed's Table 2 value
  double spring_damping = 0;                ///< Nms/rad per metre

  // ---- flexible
  std::string body_file;
  int modes = -1;                                   ///< first n modes of the file (-1: all)
  double modal_damping = 0;                         ///< zeta of every mode
  double rayleigh_mass = 0, rayleigh_stiffness = 0; ///< alpha (1/s), beta (s)
  std::string probe_set = "tip";                    ///< node set whose mean is the probe
  /// Clamped beam-like body: rebuild the skin with large-rotation kinematics from the
  /// linear rotation field (large_rotation_beam_skin.h); needs `clamp_set`, probe_set.
  bool large_rotation = false;
  std::string clamp_set = "clamp";

  // ---- fmu (also: clamped, position, angle, rho_infinity, max_step, damping, probe_set)
  std::string fmu_file;

  // ---- sph solid (Table 1 defaults)
  sph::SolidMaterial solid;
  double solid_spacing = 1e-3; ///< m, along the strip
  int solid_layers = 6;
  int clamp_rows = 4, clamp_columns = 8;
  double smoothing_factor = 1.3;                      ///< h / spacing
  Eigen::Vector2d direction = Eigen::Vector2d(0, -1); ///< clamped end -> free end
};

/// "rigid", "chain", "flexible", "sph solid" (also "sph-solid"), "fmu"; InputError otherwise.
BodyKind parse_body_kind(const std::string& word, const std::string& where);
std::string to_string(BodyKind kind);
} // namespace chipflex::coupling
