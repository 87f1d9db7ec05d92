#pragma once
// The one exception type for bad input (files, options, case keys). `main` catches it
// once, prints its message as a single line on stderr and exits non-zero.

#include <stdexcept>
#include <string>

namespace chipflex
{
class InputError : public std::runtime_error
{
public:
  /// @param where the file (and place in it), option or case key at fault
  /// @param problem what is wrong and, where useful, what was expected
  InputError(const std::string& where, const std::string& problem)
      : std::runtime_error(where + ": " + problem)
  {
  }
};

/// A simulation that cannot go on (NaN, particles leaving the domain, a collapsing
/// time step). Carries one line naming the step, time and culprit.
class SimulationError : public std::runtime_error
{
public:
  explicit SimulationError(const std::string& message) : std::runtime_error(message) {}
};
} // namespace chipflex
