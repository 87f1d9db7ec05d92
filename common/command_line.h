#pragma once
// A small, strict command-line parser for the subcommands and the benchmarks: declared options with
// help text and defaults, positional arguments, `--help`. An unknown option, a missing value or a
// value of the wrong type throws InputError naming the option.

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace chipflex::common
{
class CommandLine
{
public:
  /// @param usage e.g. "chipflex reduce MESH.msh -o BODY.h5 [options]"
  CommandLine(std::string usage, std::string summary);

  /// An option taking a value; `default_value` empty and `required` false = optional.
  void add_option(const std::string& name, const std::string& value_name, const std::string& help,
                  const std::string& default_value = "", bool required = false);
  /// An option that may be given several times (e.g. --static-modes).
  void add_repeated_option(const std::string& name, const std::string& value_name,
                           const std::string& help);
  void add_flag(const std::string& name, const std::string& help);
  void add_positional(const std::string& name, const std::string& help, bool required = true);
  /// Short alias, e.g. alias("-o", "--output").
  void add_alias(const std::string& alias, const std::string& name);

  /// Returns false if --help was given (the help text has been printed to stdout).
  bool parse(const std::vector<std::string>& args);
  std::string help() const;

  bool has(const std::string& name) const;
  bool flag(const std::string& name) const;
  std::string get(const std::string& name) const;
  std::vector<std::string> get_all(const std::string& name) const;
  double get_double(const std::string& name) const;
  long get_int(const std::string& name) const;

private:
  struct Option
  {
    std::string name, value_name, help, default_value;
    bool is_flag = false, required = false, repeated = false, positional = false;
  };
  const Option& option(const std::string& name) const;

  std::string usage_, summary_;
  std::vector<Option> options_;
  std::map<std::string, std::string> aliases_;
  std::map<std::string, std::vector<std::string>> values_;
};
} // namespace chipflex::common
