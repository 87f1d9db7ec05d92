// `chipflex plot RUN... --out PNG`: the elastic gate benchmark's figure and error — the
// gate's free-end displacement dx and dy against time for every run given, with the
// Antoci 2007 experiment and the published numerical curves (data/antoci2007/), and each
// run's RMS error against the experiment (printed, one `rms:` line per run).
// Drawn by gnuplot (Debian's gnuplot-nox, pngcairo terminal, png as fallback); the
// curves are first rewritten as plain whitespace tables in a temporary folder.

#include "apps/commands.h"
#include "common/atomic_output.h"
#include "common/command_line.h"
#include "common/input_error.h"
#include "coupling/displacement_history.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace chipflex::apps
{
namespace
{
namespace fs = std::filesystem;
using coupling::DisplacementHistory;

struct Curve
{
  std::string label, file, style;
  int component; ///< -1: both (dx in column 2, dy in 3), 0 / 1: one component in column 2
};

/// A run folder's displacement CSV (the first *_displacement.csv, by name), or the file.
std::string displacement_file(const std::string& run)
{
  if (fs::is_regular_file(run))
    return run;
  if (!fs::is_directory(run))
    throw InputError(run, "neither a run folder nor a CSV file");
  std::vector<std::string> found;
  for (const auto& entry : fs::directory_iterator(run))
  {
    const std::string name = entry.path().filename().string();
    if (name.size() > 17 && name.substr(name.size() - 17) == "_displacement.csv")
      found.push_back(entry.path().string());
  }
  if (found.empty())
    throw InputError(run, "no *_displacement.csv in this folder (is it a coupled run?)");
  std::sort(found.begin(), found.end());
  return found.front();
}

std::string write_table(const DisplacementHistory& h, const std::string& path)
{
  std::ofstream out(path);
  out.precision(10);
  for (std::size_t i = 0; i < h.size(); ++i)
    out << h.time()[i] << ' ' << h.dx()[i] * 1e3 << ' ' << h.dy()[i] * 1e3 << '\n';
  if (!out)
    throw InputError(path, "cannot write");
  return path;
}

std::string find_data_folder(const std::string& given)
{
  if (!given.empty())
  {
    if (!fs::is_directory(given))
      throw InputError("--data", "'" + given + "' is not a folder");
    return given;
  }
  for (const std::string& candidate :
       {std::string("data/antoci2007"), std::string(CHIPFLEX_PLOT_DATA_DIR)})
    if (fs::is_directory(candidate))
      return candidate;
  throw InputError("--data", "data/antoci2007 not found; give --data DIR");
}
} // namespace

int plot_command(const Arguments& args)
{
  common::CommandLine cl("chipflex plot RUN... --out PNG [options]",
                         "Plot the gate's free-end displacement (dx, dy) against time for each RUN "
                         "(a `chipflex run` output folder or a CSV time_s,dx_m,dy_m) with the "
                         "experiment and published curves of Antoci et al. 2007.");
  cl.add_positional("RUN", "run folders or displacement CSV files (one or more)", true);
  cl.add_option("--out", "PNG", "output image", "elastic_gate.png");
  cl.add_option("--data", "DIR", "reference data folder (default: data/antoci2007)");
  cl.add_option("--title", "TEXT", "figure title", "Elastic gate (Antoci et al. 2007)");
  cl.add_option("--labels", "A,B,...", "curve labels for the runs (default: folder names)");
  cl.add_option("--gnuplot", "PROGRAM", "gnuplot executable", "gnuplot");
  cl.add_option("--error-window", "T0,T1",
                "experiment frames inside [T0, T1] enter the RMS error, s (the published "
                "errors' window, data/antoci2007/README.md)",
                "0.04,0.36");
  // The parser takes one positional; the further runs are split off here (every
  // option but --help takes a value).
  std::vector<std::string> runs, rest;
  bool first_run_seen = false;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    if (a.rfind("-", 0) == 0)
    {
      rest.push_back(a);
      if (a != "--help" && a != "-h" && a.find('=') == std::string::npos && i + 1 < args.size())
        rest.push_back(args[++i]);
    }
    else if (!first_run_seen)
    {
      rest.push_back(a); // the first run: the declared positional
      first_run_seen = true;
    }
    else
      runs.push_back(a);
  }
  if (!cl.parse(rest))
    return 0;
  runs.insert(runs.begin(), cl.get("RUN"));

  std::vector<std::string> labels;
  if (cl.has("--labels"))
  {
    std::stringstream s(cl.get("--labels"));
    std::string l;
    while (std::getline(s, l, ','))
      labels.push_back(l);
    if (labels.size() != runs.size())
      throw InputError("--labels", std::to_string(labels.size()) + " labels for " +
                                       std::to_string(runs.size()) + " runs");
  }
  const std::string data = find_data_folder(cl.has("--data") ? cl.get("--data") : "");
  const fs::path work = fs::temp_directory_path() / ("chipflex_plot_" + std::to_string(::getpid()));
  fs::create_directories(work);

  std::vector<Curve> curves;
  std::vector<DisplacementHistory> histories;
  const char* run_colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  for (std::size_t r = 0; r < runs.size(); ++r)
  {
    histories.push_back(DisplacementHistory::read_csv(displacement_file(runs[r])));
    const auto& h = histories.back();
    const std::string label = labels.empty() ? fs::path(runs[r]).filename().string() : labels[r];
    curves.push_back({label.empty() ? runs[r] : label,
                      write_table(h, (work / ("run" + std::to_string(r) + ".dat")).string()),
                      std::string("lines lw 2.5 lc rgb '") + run_colours[r % 6] + "'", -1});
  }
  const auto experiment = DisplacementHistory::read_csv(data + "/experiment_merged.csv");
  double t0 = 0, t1 = 0;
  {
    const std::string w = cl.get("--error-window");
    char comma = 0;
    std::istringstream in(w);
    if (!(in >> t0 >> comma >> t1) || comma != ',' || !(t1 > t0))
      throw InputError("--error-window", "'" + w + "' is not T0,T1 with T1 > T0");
  }
  // Each run against the experiment, before anything is drawn: a run that ends before
  // the window does is an error (DisplacementHistory::rms_error), not a good score.
  std::ostringstream rms;
  rms.setf(std::ios::fixed);
  rms.precision(2);
  for (std::size_t r = 0; r < runs.size(); ++r)
  {
    const auto e = histories[r].rms_error(experiment, t0, t1);
    rms << "rms: run=" << curves[r].label << " rms_dx_mm=" << e.rms_dx * 1e3
        << " rms_dy_mm=" << e.rms_dy * 1e3 << " frames=" << e.frames << "\n";
  }
  curves.push_back({"experiment (Antoci 2007)",
                    write_table(experiment, (work / "experiment.dat").string()),
                    "points pt 7 ps 1.3 lc rgb 'black'", -1});
  const std::pair<const char*, const char*> published[] = {
      {"antoci2007_sph", "SPH, Antoci 2007"},
      {"khayyer2018_isph_sph", "ISPH-SPH, Khayyer 2018"},
      {"yang2012_sph_fem", "SPH-FEM, Yang 2012"}};
  int dash = 2;
  for (const auto& [stem, label] : published)
  {
    for (int c = 0; c < 2; ++c)
    {
      const auto h =
          DisplacementHistory::read_csv(data + "/" + stem + (c == 0 ? "_dx.csv" : "_dy.csv"), c);
      curves.push_back(
          {label,
           write_table(h, (work / (std::string(stem) + std::to_string(c) + ".dat")).string()),
           "lines dt " + std::to_string(dash) + " lw 1.5 lc rgb 'gray40'", c});
    }
    ++dash;
  }

  const std::string png = cl.get("--out");
  AtomicOutput output(png);
  const fs::path script = work / "plot.gp";
  {
    std::ofstream gp(script);
    gp << "set terminal pngcairo size 1400,600 font 'Sans,11' noenhanced\n"
       << "set output '" << output.temporary_path() << "'\n"
       << "set multiplot layout 1,2 title '" << cl.get("--title") << "'\n"
       << "set grid\nset xlabel 'time (s)'\nset xrange [0:0.4]\nset key bottom right font ',9'\n";
    for (int c = 0; c < 2; ++c)
    {
      gp << "set ylabel '" << (c == 0 ? "horizontal" : "vertical")
         << " free-end displacement (mm)'\n"
         << "set title '" << (c == 0 ? "dx (downstream positive)" : "dy (up positive)") << "'\n"
         << "plot ";
      bool first = true;
      for (const auto& curve : curves)
      {
        if (curve.component >= 0 && curve.component != c)
          continue;
        const int column = curve.component >= 0 ? 2 + curve.component : 2 + c;
        gp << (first ? "" : ", \\\n     ") << "'" << curve.file << "' using 1:" << column
           << " with " << curve.style << " title '" << curve.label << "'";
        first = false;
      }
      gp << "\n";
    }
    gp << "unset multiplot\n";
  }
  const std::string command = cl.get("--gnuplot") + " '" + script.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  if (status != 0 || !fs::exists(output.temporary_path()) ||
      fs::file_size(output.temporary_path()) == 0)
  {
    fs::remove_all(work);
    throw InputError("gnuplot", "failed to draw (is gnuplot installed? apt-get install "
                                "gnuplot-nox); command: " +
                                    command);
  }
  output.commit();
  fs::remove_all(work);
  std::cout << rms.str() << "wrote " << png << ": " << runs.size()
            << " run(s), experiment and 3 published curves" << std::endl;
  return 0;
}
} // namespace chipflex::apps
