#pragma once
// `chipflex info BODY.h5 --xdmf OUT.xdmf`: a body file's mesh and mode shapes for
// ParaView. The body file holds the reference coordinates of all FE nodes and the skin
// as linear pieces (segments in 2D, triangles in 3D), not the volume cells, so the grid
// is every node with the skin faces as its cells; each mode is a point vector array
// named after its number and frequency ("mode_1_12.35_Hz"). The heavy data goes to
// OUT.modes.h5 beside OUT.xdmf; both are written atomically. docs/output.md describes
// the datasets.

#include "common/reduced_body_file.h"

#include <string>

namespace chipflex::apps
{
/// Throws InputError for a path that cannot be written (missing or read-only folder, no
/// .xdmf/.xmf extension, or one whose HDF5 file would be `body_path` itself).
void write_body_xdmf(const ReducedBodyData& body, const std::string& body_path,
                     const std::string& xdmf_path);

/// "mode_K_F_Hz" with F the frequency to 4 digits (letters, digits, '.', '_' only).
std::string mode_array_name(int k, double frequency_hz);
} // namespace chipflex::apps
