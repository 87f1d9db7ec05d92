#pragma once
// A chip source: releases chips into a coupled run as the drill cuts (docs/chip_source.md).
//
// The chips are a pool of bodies of the case (rigid or flexible, any skin), parked where
// the case places them, away from the fluid: a parked body stands still, takes no fluid
// or contact force and touches nothing (CoSimulation::set_parked). Every `interval` from
// `first_release` on, the source takes the first parked body of the pool, puts it
// undeformed at the release pose with the release velocity (the chip leaving the cutting
// edge) and lets it go. A chip whose skin's centre passes the exit plane has left the
// segment: it is counted, put back into its parking state and can be released again as a
// later chip. So a run produces as many chips as it needs with a pool as large as the
// number of chips in the segment at once; a release that finds no parked body is skipped
// and counted. A release also waits while a chip released before it is still at the
// cutting edge (its skin's centre within the pool's largest skin radius of where a
// released chip's centre starts): put onto it, the new chip would overlap the last one and
// their contact would fling both. The wait is counted (delayed). Chips are numbered 1, 2,
// ... in the order of their release.

#include "coupling/co_simulation.h"

#include <Eigen/Core>
#include <vector>

namespace chipflex::coupling
{
template <int dim>
struct ChipSourceSettings
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  std::vector<int> pool;            ///< CoSimulation body indices, released in this order
  double first_release = 0;         ///< s
  double interval = 0;              ///< s between releases (> 0)
  Vector position = Vector::Zero(); ///< the body frame's, m
  Eigen::Matrix<double, dim, dim> rotation = Eigen::Matrix<double, dim, dim>::Identity();
  Vector velocity = Vector::Zero();                                 ///< m/s
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();       ///< rad/s (2D: z)
  Vector exit_point = Vector::Zero(), exit_normal = Vector::Zero(); ///< out: n.(x - p) > 0
};

template <int dim>
class ChipSource
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;

  /// Parks the pool's bodies (their present state is their parking state) and registers
  /// an after-step hook on the fluid, after the co-simulation's own. Throws InputError
  /// for an empty pool, a non-positive interval or a zero exit normal.
  ChipSource(CoSimulation<dim>& cosim, const ChipSourceSettings<dim>& settings);

  long released() const { return released_; }
  long removed() const { return removed_; }
  long skipped() const { return skipped_; } ///< releases that found no parked body
  long delayed() const { return delayed_; } ///< releases that waited for the edge to clear
  /// The number of the chip pool body k carries (0: parked).
  long chip_number(int k) const { return chip_[k]; }
  const ChipSourceSettings<dim>& settings() const { return settings_; }

  /// Checkpoint: the counts and which chip each pool body carries (the bodies' own state
  /// is the co-simulation's). restore() re-parks the pool accordingly.
  std::vector<double> state() const;
  void restore(const std::vector<double>& state);

private:
  void after_step(double t);
  Vector skin_centre(int body) const;
  /// Whether a chip in the segment is still within the clearance of the release point.
  bool edge_occupied() const;

  CoSimulation<dim>& cosim_;
  ChipSourceSettings<dim> settings_;
  std::vector<std::vector<double>> parking_; ///< each pool body's state when parked
  std::vector<long> chip_;
  long released_ = 0, removed_ = 0, skipped_ = 0, due_ = 0; ///< due_: releases so far
  long delayed_ = 0;
  bool waiting_ = false;  ///< a due release waits for the edge to clear
  Vector release_centre_; ///< a released chip's skin centre at the release pose
  double clearance_ = 0;  ///< the pool's largest skin radius about its centre
  mutable std::vector<Vector> nodes_;
};
} // namespace chipflex::coupling
