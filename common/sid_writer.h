#pragma once
// Standard Input Data (SID) of a flexible body (O. Wallrapp, "Standardization of flexible
// body modeling in multibody system codes, Part I: Definition of standard input data",
// Mech. Struct. Mach. 22 (1994) 283-304; R. Schwertassek, O. Wallrapp, "Dynamik flexibler
// Mehrkoerpersysteme", Vieweg 1999, ch. 6) written from a chipflex body file as the
// text layout MatMorembs and Neweul-M2 exchange (.SID_FEM): refmod, the nodes' frame
// data, and the Taylor expansions mdCM, J, Ct, Cr, Me, Gr, Ge, Oe, ksigma, Ke, De.
// Every entry, its formula in the body file's C tensors, and which first-order terms are
// absent (the body file is linear, version 1: no geometric stiffening): docs/export_fmu_sid.md.

#include "common/reduced_body_file.h"

#include <string>
#include <vector>

namespace chipflex
{
struct SidOptions
{
  /// Nodes written to the frame section (ids of the body file); empty = all nodes.
  std::vector<int> nodes;
};

/// The SID text. 2D bodies are embedded in 3D with z = 0 (per metre of depth).
std::string sid_text(const ReducedBodyData& body, const SidOptions& options = {});

/// Writes sid_text atomically.
void write_sid(const std::string& path, const ReducedBodyData& body,
               const SidOptions& options = {});
} // namespace chipflex
