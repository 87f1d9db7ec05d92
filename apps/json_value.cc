#include "apps/json_value.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <system_error>

namespace chipflex::apps
{
std::string json_number(double value)
{
  if (!std::isfinite(value))
    return "null";
  // Without a format, to_chars gives the shortest representation that parses back to the
  // same value (fixed or scientific, whichever is shorter); 32 characters hold any double.
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  if (error != std::errc())
    return "null";
  return std::string(buffer, end);
}

std::string json_string(const std::string& text)
{
  std::string out = "\"";
  for (const char c : text)
    if (c == '"' || c == '\\')
      (out += '\\') += c;
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned char>(c));
      out += escape;
    }
    else
      out += c;
  return out + "\"";
}
} // namespace chipflex::apps
