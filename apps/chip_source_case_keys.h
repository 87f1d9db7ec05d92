#pragma once
// `subsection bodies / subsection chip source` of a case file: which bodies are the chip
// source's pool, when it releases a chip, where and how fast, and where a chip leaves
// (coupling/chip_source.h, docs/chip_source.md).

#include "common/rotating_frame.h"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace dealii
{
class ParameterHandler;
}

namespace chipflex::apps
{
template <int dim>
struct ChipSourceCase
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  std::vector<std::string> bodies; ///< the pool, by name; empty: no chip source
  double first_release = 0;        ///< s
  double interval = 0;             ///< s (from `interval` or `revolutions`)
  Vector position = Vector::Zero();
  Eigen::Matrix<double, dim, dim> rotation = Eigen::Matrix<double, dim, dim>::Identity();
  Vector velocity = Vector::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  Vector exit_point = Vector::Zero(), exit_normal = Vector::Zero();
};

/// Declares the subsection; call inside `subsection bodies`.
void declare_chip_source_keys(dealii::ParameterHandler& prm);

/// Reads it (inside `subsection bodies`); `frame`: the case's turning frame, for
/// `revolutions`. `where`: "CASE: bodies, chip source".
template <int dim>
ChipSourceCase<dim> read_chip_source_keys(dealii::ParameterHandler& prm, const std::string& where,
                                          const RotatingFrame& frame);
} // namespace chipflex::apps
