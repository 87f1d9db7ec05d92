#pragma once
// `subsection bodies` of a `chipflex run` case file: up to four coupled bodies, each in
// `subsection body N` (N = 1..4) with `kind` = none | rigid | chain | flexible |
// sph solid. Every key is declared once here with its unit and default; bad values
// throw InputError naming the body, the key and the value.

#include "coupling/body_description.h"

#include <string>
#include <vector>

namespace dealii
{
class ParameterHandler;
}

namespace chipflex::apps
{
/// What the case says about the coupled run beyond the bodies themselves.
struct BodyCase
{
  std::vector<coupling::BodyDescription> bodies;
  /// Reference curve for the probe of the first body (time_s, dx_m, dy_m), empty: none.
  std::string reference_file;
  double error_window_begin = 0.04, error_window_end = 0.36; ///< s
};

/// Reads the bodies; relative file names are looked up beside the case file first,
/// then in the working directory.
BodyCase read_body_case(dealii::ParameterHandler& prm, const std::string& case_path);
} // namespace chipflex::apps
