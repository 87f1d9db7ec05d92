#pragma once
// Values in case files: trimmed text, ';'-separated items, ','-separated number lists and
// vectors, and the text of a key's default. Every section's reader (the fluid, geometry,
// open boundaries, probes, bodies, contact) parses its values with these, so that a bad
// value gives the same one-line error everywhere (InputError naming the key).

#include "common/input_error.h"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace chipflex::apps
{
/// `s` without leading and trailing blanks (spaces, tabs, line ends).
std::string trim(const std::string& s);

/// The non-blank items of `s` between `separator`s, trimmed.
std::vector<std::string> split(const std::string& s, char separator);

/// The comma-separated numbers of `text` (blank: none). InputError(key) for anything that
/// is not a number.
std::vector<double> numbers(const std::string& key, const std::string& text);

/// Exactly dim comma-separated numbers.
template <int dim>
Eigen::Matrix<double, dim, 1> vector_of(const std::string& key, const std::string& text)
{
  const auto v = numbers(key, text);
  if (v.size() != dim)
    throw InputError(key, "'" + text + "' needs " + std::to_string(dim) + " components");
  return Eigen::Map<const Eigen::Matrix<double, dim, 1>>(v.data());
}

/// A default value as the text of its key: the shortest form that reads back as the same
/// number (1e-6, 0.01, 1000), so that a key's default is the struct member's initialiser.
std::string default_text(double value);
} // namespace chipflex::apps
