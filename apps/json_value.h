#pragma once
// JSON values for the commands' --json outputs: numbers in their shortest form that reads
// back to the same double (0.3 prints as 0.3, not 0.29999999999999999), strings escaped.

#include <string>

namespace chipflex::apps
{
/// The shortest decimal that round-trips to `value` (std::to_chars); null for NaN and
/// infinities, which JSON cannot hold.
std::string json_number(double value);

/// `text` in double quotes, with '"', '\\' and control characters escaped.
std::string json_string(const std::string& text);

/// [a, b, ...] of the first n entries of any indexable vector of doubles.
template <typename Vector>
std::string json_array(const Vector& values, int n)
{
  std::string out = "[";
  for (int i = 0; i < n; ++i)
    out += (i ? ", " : "") + json_number(values[i]);
  return out + "]";
}
} // namespace chipflex::apps
