#pragma once
// Test helper: a reduced body built without fem/. A slender strip of nodes joined by bars
// (edges and diagonals: a stiff truss that bends like a beam), with the *consistent*
// scalar bar mass matrix m_e/6 [2 1; 1 2] (non-diagonal, so the invariants are those of
// a consistent mass matrix), modes from Eigen's GeneralizedSelfAdjointEigenSolver and
// the inertia invariants from their definition C(a, b) = A^T Ms B.

#include "common/reduced_body_file.h"

#include <Eigen/Dense>

namespace chipflex::mbs::test
{
struct TrussBeamSpec
{
  int dim = 2;
  int n_cells = 12;           ///< along x
  double length = 0.079;      ///< m
  double height = 0.005;      ///< m, in y
  double depth = 0.005;       ///< m, in z (3D)
  double density = 1100;      ///< kg/m^3
  double bar_stiffness = 2e5; ///< EA of every bar, N
  bool clamped = true;        ///< modes with the x = 0 nodes fixed; else free-free
  int n_modes = 6;            ///< kept (negative: all)
};

/// The reduced body, plus the full matrices for reference solutions.
struct TrussBeam
{
  ReducedBodyData body;
  Eigen::MatrixXd scalar_mass; ///< Ms, n x n
  Eigen::MatrixXd stiffness;   ///< K, dim n x dim n (all nodes, free-free)
};

TrussBeam make_truss_beam(const TrussBeamSpec& spec);
} // namespace chipflex::mbs::test
