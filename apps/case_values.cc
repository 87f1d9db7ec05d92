#include "apps/case_values.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

namespace chipflex::apps
{
std::string trim(const std::string& s)
{
  const auto a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos)
    return "";
  return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

std::vector<std::string> split(const std::string& s, char separator)
{
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, separator))
    if (!trim(item).empty())
      out.push_back(trim(item));
  return out;
}

std::vector<double> numbers(const std::string& key, const std::string& text)
{
  std::vector<double> out;
  for (const auto& item : split(text, ','))
  {
    std::size_t used = 0;
    double v = 0;
    try
    {
      v = std::stod(item, &used);
    }
    catch (const std::exception&)
    {
      used = 0;
    }
    if (used != item.size())
      throw InputError(key, "'" + text + "' is not a list of numbers");
    out.push_back(v);
  }
  return out;
}

std::string default_text(double value)
{
  char text[32];
  for (int digits = 1; digits <= 17; ++digits)
  {
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    // Exponent form only for very small or large values (1e-6, not 1e3 for 1000).
    const bool plain_wanted = std::abs(value) >= 1e-4 && std::abs(value) < 1e15;
    if (std::stod(text) == value && (!plain_wanted || !std::strchr(text, 'e')))
      break;
  }
  // printf writes the exponent with at least two digits: 1e-06 -> 1e-6.
  std::string s = text;
  const auto e = s.find('e');
  if (e != std::string::npos)
  {
    std::size_t k = e + 1 + (s[e + 1] == '-' || s[e + 1] == '+');
    while (k + 1 < s.size() && s[k] == '0')
      s.erase(k, 1);
    if (s[e + 1] == '+')
      s.erase(e + 1, 1);
  }
  return s;
}
} // namespace chipflex::apps
