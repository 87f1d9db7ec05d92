#include "fem/load_case.h"

#include "common/input_error.h"

#include <cstdlib>
#include <sstream>

namespace chipflex::fem
{
LoadCase LoadCase::parse(const std::string& text, int dim, const std::string& option)
{
  const std::string where = option + " " + text;
  LoadCase load;
  load.text = text;
  const auto colon = text.find(':');
  if (colon == std::string::npos)
    throw InputError(where, "expected pressure:GROUP or force:GROUP:fx,fy[,fz]");
  const std::string kind = text.substr(0, colon);
  std::string rest = text.substr(colon + 1);
  if (kind == "pressure")
  {
    load.kind = Kind::pressure;
    load.group = rest;
  }
  else if (kind == "force")
  {
    load.kind = Kind::force;
    const auto c2 = rest.find(':');
    if (c2 == std::string::npos)
      throw InputError(where, "expected force:GROUP:fx,fy[,fz]");
    load.group = rest.substr(0, c2);
    std::stringstream values(rest.substr(c2 + 1));
    std::string item;
    while (std::getline(values, item, ','))
    {
      char* end = nullptr;
      const double v = std::strtod(item.c_str(), &end);
      if (item.empty() || *end != '\0')
        throw InputError(where, "'" + item + "' is not a number");
      load.force.push_back(v);
    }
    if (static_cast<int>(load.force.size()) != dim)
      throw InputError(where, "the force needs " + std::to_string(dim) + " components for a " +
                                  std::to_string(dim) + "D body");
  }
  else
    throw InputError(where, "unknown load kind '" + kind + "' (expected pressure or force)");
  if (load.group.empty())
    throw InputError(where, "missing group name");
  return load;
}
} // namespace chipflex::fem
