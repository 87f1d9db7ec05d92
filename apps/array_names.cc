#include "apps/array_names.h"

#include <cctype>

namespace chipflex::apps
{
std::string name_with_unit(const std::string& name, const std::string& unit)
{
  if (unit.empty() || unit == "-")
    return name;
  std::string spelt;
  for (const char c : unit)
    if (std::isalnum(static_cast<unsigned char>(c)))
      spelt += c;
    else if (c != '^' && !spelt.empty() && spelt.back() != '_')
      // "^" only raises a power ("m^3" -> "m3"); "/", " " and "." separate.
      spelt += '_';
  return name + "_" + spelt;
}
} // namespace chipflex::apps
