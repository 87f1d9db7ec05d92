#include "apps/case_file.h"

#include "apps/body_case_keys.h"
#include "apps/case_values.h"
#include "apps/contact_case_keys.h"
#include "apps/fluid_case_keys.h"
#include "apps/geometry_case_keys.h"
#include "apps/open_boundary_case_keys.h"
#include "apps/probe_case_keys.h"
#include "common/input_error.h"

#include <deal.II/base/parameter_handler.h>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace chipflex::apps
{
using dealii::ParameterHandler;
using dealii::Patterns::Integer;

namespace
{
/// Every key of a case file, section by section (each section's keys, defaults and
/// documentation live in its own file).
void declare_keys(ParameterHandler& prm, int n_bodies)
{
  prm.declare_entry("dimension", "2", Integer(2, 3), "Space dimension: 2 (per metre depth) or 3.");
  declare_fluid_keys(prm);
  declare_geometry_keys(prm);
  declare_open_boundary_keys(prm);
  declare_probe_keys(prm);
  declare_body_keys(prm, n_bodies);
  declare_contact_keys(prm);
}

template <int dim>
void fill(ParameterHandler& prm, sph::CaseDescription<dim>& c, const std::string& case_path)
{
  const std::string shifting = read_fluid_keys(prm, c);
  read_geometry_keys(prm, c, case_path);
  read_open_boundary_keys(prm, c);
  // An internal flow (an inlet or an outlet) is shifted unless the case says otherwise.
  if (shifting == "automatic" && c.open_boundaries.empty())
    c.fluid.shifting_coefficient = 0;
  read_probe_keys(prm, c);
}

/// deal.II's exception text is a multi-line block; keep its "additional information"
/// as one line.
std::string one_line(const std::string& what)
{
  std::string s = what;
  const auto info = s.find("Additional information:");
  if (info != std::string::npos)
    s = s.substr(info + 23);
  const auto stack = s.find("Stacktrace:");
  if (stack != std::string::npos)
    s = s.substr(0, stack);
  std::string out;
  bool space = false;
  for (char ch : s)
  {
    if (ch == '\n' || ch == '\t' || ch == ' ')
      space = !out.empty();
    else
    {
      if (space)
        out += ' ';
      out += ch;
      space = false;
    }
  }
  while (!out.empty() && (out.back() == '-' || out.back() == ' '))
    out.pop_back();
  return out;
}
} // namespace

// declare_body_keys(): apps/body_case_keys.cc (the coupled bodies' keys).

std::string documented_case_keys()
{
  ParameterHandler prm;
  declare_keys(prm, 1);
  std::ostringstream out;
  prm.print_parameters(out, ParameterHandler::OutputStyle::PRM);
  return out.str();
}

namespace
{
/// The case file's text with every `include FILE` line (FILE relative to the case file's
/// folder) given as an absolute path, for ParameterHandler, which reads the included file
/// in its place (so its errors name that file and its line); and, in `expanded`, the text
/// with each included file written out, for what must see the whole case before it is
/// parsed (the body subsections). One level: an included file includes nothing.
/// Where an `include ` statement starts in `line`, or npos.
std::size_t include_at(const std::string& line)
{
  const std::size_t first = line.find_first_not_of(" \t");
  return first != std::string::npos && line.compare(first, 8, "include ") == 0 ? first
                                                                               : std::string::npos;
}

std::string resolve_includes(const std::string& path, std::string& expanded)
{
  std::ifstream in(path);
  if (!in)
    throw InputError(path, "cannot open the case file");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::string resolved, line;
  expanded.clear();
  for (int line_number = 1; std::getline(in, line); ++line_number)
  {
    const std::size_t first = include_at(line);
    if (first == std::string::npos)
    {
      resolved += line + "\n";
      expanded += line + "\n";
      continue;
    }
    const std::string where = path + ": line " + std::to_string(line_number);
    const std::string name = trim(line.substr(first + 8));
    if (name.empty())
      throw InputError(where, "include: no file name");
    const std::filesystem::path file = std::filesystem::absolute(folder / name);
    std::ifstream included(file);
    if (!included)
      throw InputError(where, "include " + name + ": cannot open " + file.string());
    std::stringstream text;
    text << included.rdbuf();
    std::istringstream lines(text.str());
    for (std::string l; std::getline(lines, l);)
      if (include_at(l) != std::string::npos)
        throw InputError(file.string(), "include inside an included file (one level only)");
    resolved += "include " + file.string() + "\n";
    expanded += text.str() + "\n";
  }
  return resolved;
}
} // namespace

CaseFile read_case_file(const std::string& path)
{
  std::string expanded;
  std::stringstream text(resolve_includes(path, expanded));
  CaseFile c;
  c.path = path;
  c.parameters = std::make_shared<ParameterHandler>();
  auto& prm = *c.parameters;
  c.body_subsections = count_body_subsections(expanded);
  declare_keys(prm, c.body_subsections);
  try
  {
    prm.parse_input(text, path, "", false);
  }
  catch (const dealii::ExceptionBase& e)
  {
    throw InputError(path, one_line(e.what()));
  }
  try
  {
    c.dimension = int(prm.get_integer("dimension"));
    if (c.dimension == 2)
      fill(prm, c.case_2d, path);
    else
      fill(prm, c.case_3d, path);
    prm.enter_subsection("time");
    const bool automatic_scheme = prm.get("scheme") == "automatic";
    prm.leave_subsection();
    if (n_case_bodies(prm, c.body_subsections) > 0)
    {
      if (automatic_scheme)
        c.case_2d.fluid.scheme = c.case_3d.fluid.scheme = sph::TimeScheme::position_verlet;
      // The Verlet step's velocity update spans two steps, so the coupling's momentum
      // exchange would not be exact (docs/coupling.md).
      if (!sph::is_symplectic(c.dimension == 2 ? c.case_2d.fluid.scheme : c.case_3d.fluid.scheme))
        throw InputError("time/scheme", "'verlet': a case with bodies needs symplectic or "
                                        "position verlet (or automatic, the default)");
    }
    c.end_time = c.dimension == 2 ? c.case_2d.end_time : c.case_3d.end_time;
    c.frame_interval = c.dimension == 2 ? c.case_2d.output_interval : c.case_3d.output_interval;
    c.jam_watch = c.dimension == 2 ? read_jam_watch_keys(*c.parameters, c.case_2d)
                                   : read_jam_watch_keys(*c.parameters, c.case_3d);
    prm.enter_subsection("output");
    c.probe_interval = prm.get_double("probe interval");
    prm.leave_subsection();
    const bool open =
        c.dimension == 2 ? !c.case_2d.open_boundaries.empty() : !c.case_3d.open_boundaries.empty();
    prm.enter_subsection("open boundaries");
    if (open)
      c.tear_warning_fraction = prm.get_double("tear warning fraction");
    for (double f : numbers("open boundaries/watched frequencies", prm.get("watched frequencies")))
    {
      if (!(f > 0))
        throw InputError("open boundaries/watched frequencies",
                         "'" + prm.get("watched frequencies") + "': frequencies must be positive");
      c.watched_frequencies.push_back(f);
    }
    prm.leave_subsection();
  }
  catch (const InputError& e)
  {
    throw InputError(path, e.what());
  }
  return c;
}
} // namespace chipflex::apps
