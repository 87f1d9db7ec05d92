#pragma once
// Test reader of Standard Input Data (SID) text files, written from the layout of
// Wallrapp (1994) / Schwertassek & Wallrapp (1999) and the entry definitions of
// docs/export_fmu_sid.md, independently of the writer (common/sid_writer.cc): it parses
// the blocks generically and rebuilds the body file's invariants by inverting the
// documented formulas.

#include "common/reduced_body_file.h"

#include <Eigen/Dense>
#include <map>
#include <string>
#include <vector>

namespace chipflex::test
{
struct SidExpansion
{
  int order = 0, nrow = 0, ncol = 0, nq = 0, structure = 3;
  Eigen::MatrixXd m0;
  std::vector<Eigen::MatrixXd> m1;
};

struct Sid
{
  double mass = 0;
  int nelastq = 0;
  std::vector<std::string> ielastq;
  std::vector<std::map<std::string, SidExpansion>> nodes; ///< origin, phi, psi, AP
  std::vector<int> fe_nodes;                              ///< "fe node" of each node
  std::map<std::string, SidExpansion> modal;              ///< mdCM, J, Ct, ...
};

/// Parses a SID file; throws std::runtime_error naming the line for anything unexpected.
Sid read_sid(const std::string& path);

/// The body-file quantities the SID holds (nodes and modes of the written nodes, inertia
/// invariants, reduced matrices) for a body of dimension dim (2: z dropped).
ReducedBodyData body_from_sid(const Sid& sid, int dim);
} // namespace chipflex::test
