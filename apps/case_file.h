#pragma once
// Reading a `chipflex run` case file (deal.II ParameterHandler format). Every key is
// declared once with its unit and default, in the file of its section:
// apps/fluid_case_keys (fluid, time, output), geometry_case_keys, open_boundary_case_keys,
// probe_case_keys, body_case_keys, contact_case_keys (`chipflex run --print-keys` prints
// them all); values are parsed with apps/case_values. An unknown key, a bad value or a missing file
// throws InputError naming the file, the key and the value.
//
// The case fills plain sph:: structs; the raw ParameterHandler stays available so that
// coupling/ can read `subsection bodies` (declared in declare_body_keys()).

#include "apps/jam_watch.h"
#include "sph/case_setup.h"

#include <memory>
#include <string>
#include <vector>

namespace dealii
{
class ParameterHandler;
}

namespace chipflex::apps
{
struct CaseFile
{
  std::string path;
  int dimension = 2;
  double end_time = 1, frame_interval = 0.01, probe_interval = 0.001; ///< s
  sph::CaseDescription<2> case_2d;
  sph::CaseDescription<3> case_3d;
  int body_subsections = 0; ///< highest N of the file's `subsection body N`
  /// `open boundaries/tear warning fraction` (apps/fluid_continuity.h); with no open
  /// boundary the fluid cannot leave, and the check is off.
  double tear_warning_fraction = 1;
  /// `probes/jam watch` (apps/jam_watch.h); off unless it names a gauge.
  JamWatchSettings jam_watch;
  /// `open boundaries/watched frequencies`, Hz (apps/channel_acoustics.h).
  std::vector<double> watched_frequencies;
  /// The parsed file (for subsections that other layers read, e.g. bodies).
  std::shared_ptr<dealii::ParameterHandler> parameters;
};

CaseFile read_case_file(const std::string& path);

/// All keys with their documentation and defaults, in ParameterHandler's .prm format.
std::string documented_case_keys();
} // namespace chipflex::apps
