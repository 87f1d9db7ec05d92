#include "common/command_line.h"

#include "common/input_error.h"

#include <cctype>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace chipflex::common
{
CommandLine::CommandLine(std::string usage, std::string summary)
    : usage_(std::move(usage)), summary_(std::move(summary))
{
  add_flag("--help", "print this help and exit");
}

void CommandLine::add_option(const std::string& name, const std::string& value_name,
                             const std::string& help, const std::string& default_value,
                             bool required)
{
  options_.push_back({name, value_name, help, default_value, false, required, false, false});
}

void CommandLine::add_repeated_option(const std::string& name, const std::string& value_name,
                                      const std::string& help)
{
  options_.push_back({name, value_name, help, "", false, false, true, false});
}

void CommandLine::add_flag(const std::string& name, const std::string& help)
{
  options_.push_back({name, "", help, "", true, false, false, false});
}

void CommandLine::add_positional(const std::string& name, const std::string& help, bool required)
{
  options_.push_back({name, name, help, "", false, required, false, true});
}

void CommandLine::add_alias(const std::string& alias, const std::string& name)
{
  aliases_[alias] = name;
}

const CommandLine::Option& CommandLine::option(const std::string& name) const
{
  for (const auto& o : options_)
    if (o.name == name)
      return o;
  throw std::logic_error("CommandLine: undeclared option " + name);
}

bool CommandLine::parse(const std::vector<std::string>& args)
{
  std::size_t next_positional = 0;
  std::vector<const Option*> positionals;
  for (const auto& o : options_)
    if (o.positional)
      positionals.push_back(&o);

  for (std::size_t i = 0; i < args.size(); ++i)
  {
    std::string arg = args[i];
    std::optional<std::string> inline_value;
    if (arg.rfind("--", 0) == 0 && arg.find('=') != std::string::npos)
    {
      inline_value = arg.substr(arg.find('=') + 1);
      arg = arg.substr(0, arg.find('='));
    }
    if (aliases_.count(arg))
      arg = aliases_.at(arg);
    if (arg == "--help" || arg == "-h")
    {
      std::cout << help();
      return false;
    }
    if (arg.size() > 1 && arg[0] == '-' && !(std::isdigit(arg[1]) || arg[1] == '.'))
    {
      const Option* o = nullptr;
      for (const auto& candidate : options_)
        if (!candidate.positional && candidate.name == arg)
          o = &candidate;
      if (!o)
        throw InputError("option " + arg, "unknown option (see --help)");
      if (o->is_flag)
      {
        if (inline_value)
          throw InputError("option " + arg, "takes no value");
        values_[o->name] = {"1"};
        continue;
      }
      std::string value;
      if (inline_value)
        value = *inline_value;
      else if (i + 1 < args.size())
        value = args[++i];
      else
        throw InputError("option " + arg, "needs a value <" + o->value_name + ">");
      if (o->repeated)
        values_[o->name].push_back(value);
      else
        values_[o->name] = {value};
      continue;
    }
    if (next_positional >= positionals.size())
      throw InputError("argument '" + arg + "'", "unexpected (see --help)");
    values_[positionals[next_positional++]->name] = {arg};
  }
  for (const auto& o : options_)
    if (o.required && !values_.count(o.name))
      throw InputError(o.positional ? "argument " + o.name : "option " + o.name,
                       "is required (see --help)");
  return true;
}

std::string CommandLine::help() const
{
  std::ostringstream s;
  s << "usage: " << usage_ << "\n\n" << summary_ << "\n";
  bool any_positional = false;
  for (const auto& o : options_)
    any_positional |= o.positional;
  if (any_positional)
  {
    s << "\narguments:\n";
    for (const auto& o : options_)
      if (o.positional)
        s << "  " << o.name << "\n      " << o.help << "\n";
  }
  s << "\noptions:\n";
  for (const auto& o : options_)
  {
    if (o.positional)
      continue;
    s << "  " << o.name;
    for (const auto& [alias, target] : aliases_)
      if (target == o.name)
        s << ", " << alias;
    if (!o.is_flag)
      s << " <" << o.value_name << ">";
    s << "\n      " << o.help;
    if (!o.default_value.empty())
      s << " (default: " << o.default_value << ")";
    if (o.required)
      s << " (required)";
    if (o.repeated)
      s << " (may be repeated)";
    s << "\n";
  }
  return s.str();
}

bool CommandLine::has(const std::string& name) const
{
  return values_.count(name) || !option(name).default_value.empty();
}

bool CommandLine::flag(const std::string& name) const
{
  return option(name).is_flag && values_.count(name);
}

std::string CommandLine::get(const std::string& name) const
{
  const auto it = values_.find(name);
  if (it != values_.end())
    return it->second.back();
  return option(name).default_value;
}

std::vector<std::string> CommandLine::get_all(const std::string& name) const
{
  const auto it = values_.find(name);
  return it == values_.end() ? std::vector<std::string>{} : it->second;
}

double CommandLine::get_double(const std::string& name) const
{
  const std::string value = get(name);
  char* end = nullptr;
  const double x = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0')
    throw InputError("option " + name, "'" + value + "' is not a number");
  return x;
}

long CommandLine::get_int(const std::string& name) const
{
  const std::string value = get(name);
  char* end = nullptr;
  const long x = std::strtol(value.c_str(), &end, 10);
  if (value.empty() || *end != '\0')
    throw InputError("option " + name, "'" + value + "' is not an integer");
  return x;
}
} // namespace chipflex::common
