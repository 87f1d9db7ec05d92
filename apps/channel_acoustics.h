#pragma once
// The acoustic trap of weakly-compressible channel flows. The fluid's artificial speed of
// sound c0 makes a channel of length L between a velocity inlet (acoustically closed) and
// a pressure outlet (open) ring at its quarter-wave frequency c0 / (4 L). A start-up
// transient or a pressure jump excites it; when it lies near a body's first natural
// frequency or near a frequency the case is meant to resolve (a forcing, a vortex
// shedding), the ringing drives the body and is taken for its response. Turek & Hron's
// FSI2 (2 Hz) in its 2.5 m channel rings at 2 Hz with c0 = 20 m/s. `chipflex run` warns
// when the two are within a factor of 3 (docs/sph.md, "Choosing c0 for channels").

#include "sph/case_setup.h"

#include <string>
#include <utility>
#include <vector>

namespace chipflex::apps
{
/// The channel's length along its open boundaries' axis: between the inlet's and the
/// outlet's planes when the case has both on one axis, else the fluid blocks' extent along
/// the first zone's axis; 0 without open boundaries (a closed tank has no such mode).
template <int dim>
double channel_length(const sph::CaseDescription<dim>& c);

/// Warning lines (empty: none) for each named frequency (Hz, > 0) within a factor of
/// 3 of c0 / (4 L).
std::vector<std::string>
acoustic_warnings(double speed_of_sound, double length,
                  const std::vector<std::pair<std::string, double>>& frequencies);
} // namespace chipflex::apps
