// `chipflex simulate BODY.h5 --end-time T -o CSV [--load force:GROUP:fx,fy[,fz]] ...`: a
// reduced body on its own, without fluid, under a load history: the check a user makes
// before coupling a body (does it fall, spin, ring as expected?). The body is the same
// mbs::FloatingFrameBody that `chipflex run` couples, integrated with the same
// generalised-alpha scheme, free-floating unless --clamped.
//
// The load: a total force (N; 2D: N per metre of depth) shared equally by the nodes of a
// named node set of the body file, times the factor of --history (a CSV `time_s,factor`,
// linear between rows, held after the last; default 1 from t = 0, a step load). An equal
// share gives the exact resultant and moment about the set's node centroid, which is
// what the frame motion sees; the FE-consistent nodal distribution (`compare`) differs
// only in how the set's own deformation is excited.

#include "apps/commands.h"
#include "common/atomic_output.h"
#include "common/command_line.h"
#include "common/input_error.h"
#include "common/reduced_body_file.h"
#include "fem/load_case.h"
#include "mbs/multibody_system.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace chipflex::apps
{
namespace
{
/// (time, factor) rows of a load-history CSV, in increasing time.
std::vector<std::pair<double, double>> read_history(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
    throw InputError(path, "cannot open the load history");
  std::vector<std::pair<double, double>> rows;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number)
  {
    if (line.empty() || line[0] == '#' || (number == 1 && line.find("time") != std::string::npos))
      continue;
    std::stringstream s(line);
    double t = 0, f = 0;
    char comma = 0;
    if (!(s >> t >> comma >> f) || comma != ',' || !std::isfinite(t) || !std::isfinite(f))
      throw InputError(path + ":" + std::to_string(number), "expected 'time_s,factor'");
    if (!rows.empty() && !(t > rows.back().first))
      throw InputError(path + ":" + std::to_string(number), "times must increase");
    rows.emplace_back(t, f);
  }
  if (rows.empty())
    throw InputError(path, "the load history has no rows");
  return rows;
}

double factor_at(const std::vector<std::pair<double, double>>& rows, double t)
{
  if (rows.empty())
    return 1;
  if (t <= rows.front().first)
    return rows.front().second;
  for (std::size_t k = 1; k < rows.size(); ++k)
    if (t <= rows[k].first)
    {
      const auto& [t0, f0] = rows[k - 1];
      const auto& [t1, f1] = rows[k];
      return f0 + (f1 - f0) * (t - t0) / (t1 - t0);
    }
  return rows.back().second;
}

template <int dim>
void simulate(const ReducedBodyData& data, const common::CommandLine& cl)
{
  using Vector = Eigen::Matrix<double, dim, 1>;
  const double end_time = cl.get_double("--end-time"), dt = cl.get_double("--dt");
  if (!(end_time > 0))
    throw InputError("--end-time", "must be positive");
  if (!(dt > 0) || dt > end_time)
    throw InputError("--dt", "must be positive and not above the end time");

  mbs::MultibodySystem<dim> system;
  auto owned = std::make_unique<mbs::FloatingFrameBody<dim>>(data);
  auto& body = *owned;
  system.add_body(std::move(owned));
  if (cl.flag("--clamped"))
    body.clamp_to_ground();
  if (cl.has("--gravity"))
  {
    const auto g = fem::LoadCase::parse("force:g:" + cl.get("--gravity"), dim, "--gravity");
    system.set_gravity(Eigen::Map<const Vector>(g.force.data()));
  }
  std::vector<int> nodes;
  Vector total = Vector::Zero();
  if (cl.has("--load"))
  {
    const auto load = fem::LoadCase::parse(cl.get("--load"), dim, "--load");
    if (load.kind != fem::LoadCase::Kind::force)
      throw InputError("--load " + load.text, "simulate takes force:GROUP:fx,fy[,fz]");
    nodes = body.node_set(load.group);
    if (nodes.empty())
      throw InputError("--load " + load.text, "node set '" + load.group + "' is empty");
    total = Eigen::Map<const Vector>(load.force.data());
  }
  const auto history = cl.has("--history") ? read_history(cl.get("--history"))
                                           : std::vector<std::pair<double, double>>{};

  const std::string path = cl.get("--output");
  AtomicOutput output(path);
  {
    std::ofstream out(output.temporary_path());
    const char* axis[] = {"x", "y", "z"};
    out << "time_s,load_factor";
    for (int d = 0; d < dim; ++d)
      out << ",frame_" << axis[d] << "_m";
    if constexpr (dim == 2)
      out << ",frame_angle_rad";
    for (int d = 0; d < dim; ++d)
      out << ",momentum_" << axis[d] << "_Ns";
    out << ",q_norm,kinetic_J,strain_J\n" << std::setprecision(12);
    const auto row = [&](double factor)
    {
      out << system.time() << "," << factor;
      for (int d = 0; d < dim; ++d)
        out << "," << body.position()(d);
      if constexpr (dim == 2)
        out << "," << body.angle();
      const Vector p = body.linear_momentum();
      for (int d = 0; d < dim; ++d)
        out << "," << p(d);
      out << "," << body.modal_coordinates().norm() << "," << body.kinetic_energy() << ","
          << body.strain_energy() << "\n";
    };
    const long n_steps = std::lround(end_time / dt);
    row(factor_at(history, 0));
    for (long s = 1; s <= n_steps; ++s)
    {
      // The load at the step's end: generalised-alpha balances the forces at t_n+1.
      const double factor = factor_at(history, s * dt);
      if (!nodes.empty())
        body.set_node_forces(
            nodes, std::vector<Vector>(nodes.size(), factor * total / double(nodes.size())));
      system.step(dt);
      if (!std::isfinite(body.modal_coordinates().norm()) || !body.position().allFinite())
        throw SimulationError("step " + std::to_string(s) +
                              ", t = " + std::to_string(system.time()) +
                              " s: the body's state is not finite (use a smaller --dt)");
      row(factor);
    }
    if (!out)
      throw InputError(path, "cannot write");
  }
  output.commit();
  std::cout << "simulated " << end_time << " s in steps of " << dt << " s: " << path << "\n"
            << "final frame position " << body.position().transpose() << " m, momentum "
            << body.linear_momentum().transpose() << " N s, |q| " << body.modal_coordinates().norm()
            << "\n";
}
} // namespace

int simulate_command(const Arguments& args)
{
  common::CommandLine cl("chipflex simulate BODY.h5 --end-time T -o CSV [options]",
                         "Integrate a reduced body on its own (no fluid) under a load history:\n"
                         "frame position, momentum, modal amplitude and energies against time.");
  cl.add_positional("BODY", "body file from chipflex reduce");
  cl.add_option("--end-time", "T", "simulated time, s");
  cl.add_option("--dt", "S", "time step, s", "1e-4");
  cl.add_option("--load", "LOAD",
                "force:SET:fx,fy[,fz]: total force on a node set of the file, shared equally "
                "by its nodes (N; 2D: N/m)");
  cl.add_option("--history", "CSV", "load factor against time: rows 'time_s,factor' (default 1)");
  cl.add_option("--gravity", "G", "gx,gy[,gz], m/s^2 (default none)");
  cl.add_flag("--clamped", "fix the frame to ground (a cantilever clamped at its file's clamp)");
  cl.add_option("--output", "CSV", "the time history");
  cl.add_alias("-o", "--output");
  if (!cl.parse(args))
    return 0;
  if (!cl.has("BODY") || !cl.has("--end-time") || !cl.has("--output"))
    throw InputError("chipflex simulate", "needs BODY.h5, --end-time and -o CSV (--help)");
  const ReducedBodyData data = read_reduced_body(cl.get("BODY"));
  if (data.dim == 2)
    simulate<2>(data, cl);
  else
    simulate<3>(data, cl);
  return 0;
}
} // namespace chipflex::apps
