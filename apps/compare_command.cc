// `chipflex compare MESH.msh BODY.h5 --load force:GROUP:fx,fy[,fz]`: can the reduced body be
// trusted for this load? Static and step-load responses of the full FE model against the
// reduced body (compare/compare_with_full.h). Runs under mpirun too; only rank 0 prints and writes.

#include "apps/commands.h"
#include "apps/json_value.h"
#include "common/atomic_output.h"
#include "common/command_line.h"
#include "common/input_error.h"
#include "compare/compare_with_full.h"
#include "fem/blas_threads.h"
#include "fem/hyperelastic_model.h"

#include <deal.II/base/mpi.h>
#include <fstream>
#include <iomanip>
#include <iostream>

namespace chipflex::apps
{
int compare_command(const Arguments& args)
{
  common::CommandLine cl(
      "chipflex compare MESH.msh BODY.h5 --load force:GROUP:fx,fy[,fz] [options]",
      "Compare a clamped reduced body with the full FE model: static response and a\n"
      "step load (Newmark average acceleration) on both, at the centroid of the loaded\n"
      "group's nodes. With --nonlinear the full model is geometrically nonlinear\n"
      "(a large load: Newton statics, Newton on every step).");
  cl.add_positional("MESH", "the mesh the body was reduced from");
  cl.add_positional("BODY", "body file from chipflex reduce (clamped)");
  cl.add_option("--load", "LOAD", "force:GROUP:fx,fy[,fz] (total force, N; 2D: N/m)", "", true);
  cl.add_option("--duration", "S", "transient length (default: 5 periods of the lowest mode)");
  cl.add_option("--dt", "S", "time step (default: 1/40 of the lowest mode's period)");
  cl.add_flag("--nonlinear",
              "full side geometrically nonlinear (total Lagrangian, the load a dead load); "
              "the reduced side's static response its own equilibrium (Newton, load increments)");
  cl.add_option("--material", "MODEL", "--nonlinear: svk or neo-hooke", "svk");
  cl.add_option("--increments", "N", "--nonlinear: static load increments", "10");
  cl.add_flag("--json", "print one JSON object");
  cl.add_option("--output", "CSV", "time histories of both models");
  cl.add_option("--blas-threads", "N",
                "OpenBLAS threads per process (more than 1 helps only on an idle machine; "
                "use mpirun -np N for parallelism)",
                "1");
  cl.add_alias("-o", "--output");
  if (!cl.parse(args))
    return 0;
  if (cl.get_int("--blas-threads") < 1)
    throw InputError("--blas-threads", "must be at least 1");
  fem::set_blas_threads(int(cl.get_int("--blas-threads")));
  compare::CompareSettings settings;
  settings.mesh_file = cl.get("MESH");
  settings.body_file = cl.get("BODY");
  settings.load = cl.get("--load");
  if (cl.has("--duration") && !((settings.duration = cl.get_double("--duration")) > 0))
    throw InputError("--duration", "must be positive");
  if (cl.has("--dt") && !((settings.time_step = cl.get_double("--dt")) > 0))
    throw InputError("--dt", "must be positive");
  settings.nonlinear = cl.flag("--nonlinear");
  settings.material_model = cl.get("--material");
  fem::parse_hyperelastic_model(settings.material_model, "--material");
  if (cl.get_int("--increments") < 1)
    throw InputError("--increments", "must be at least 1");
  settings.load_increments = static_cast<unsigned int>(cl.get_int("--increments"));

  int argc = 1;
  std::string name = "chipflex";
  char* argv_storage[] = {name.data(), nullptr};
  char** argv = argv_storage;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto result = compare::compare_with_full(settings);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    return 0;

  const int dim = result.static_full.size();
  if (cl.has("--output"))
  {
    const std::string path = cl.get("--output");
    AtomicOutput output(path);
    {
      std::ofstream out(output.temporary_path());
      const char* axis[] = {"x", "y", "z"};
      out << "time_s";
      for (const char* side : {"full", "reduced"})
        for (int d = 0; d < dim; ++d)
          out << "," << side << "_u" << axis[d] << "_m";
      out << "\n" << std::setprecision(12);
      for (std::size_t s = 0; s < result.time.size(); ++s)
      {
        out << result.time[s];
        for (int d = 0; d < dim; ++d)
          out << "," << result.transient_full(s, d);
        for (int d = 0; d < dim; ++d)
          out << "," << result.transient_reduced(s, d);
        out << "\n";
      }
      if (!out)
        throw InputError(path, "cannot write");
    }
    output.commit();
  }
  if (cl.flag("--json"))
  {
    std::cout << "{\n  \"static_rel_error\": " << json_number(result.static_rel_error)
              << ",\n  \"transient_rel_error\": " << json_number(result.transient_rel_error)
              << ",\n  \"full_seconds\": " << json_number(result.full_seconds)
              << ",\n  \"reduced_seconds\": " << json_number(result.reduced_seconds)
              << ",\n  \"static_full_m\": " << json_array(result.static_full, dim)
              << ",\n  \"static_reduced_m\": " << json_array(result.static_reduced, dim)
              << ",\n  \"n_steps\": " << result.time.size() - 1
              << ",\n  \"dt\": " << json_number(result.time.size() > 1 ? result.time[1] : 0.)
              << ",\n  \"rho_infinity_full\": " << json_number(result.rho_infinity)
              << ",\n  \"rho_infinity_reduced\": " << json_number(result.reduced_rho_infinity)
              << "\n}\n";
  }
  else
  {
    std::cout << std::setprecision(6) << "load " << settings.load << ", centroid of '"
              << result.group << "'\n"
              << "  static     full " << result.static_full.transpose() << " m, reduced "
              << result.static_reduced.transpose() << " m, relative error "
              << result.static_rel_error << "\n"
              << "  transient  " << result.time.size() - 1 << " steps of " << result.time[1]
              << " s: max relative error " << result.transient_rel_error << "\n"
              << (result.rho_infinity < 1 || result.reduced_rho_infinity < 1
                      ? "  (a trapezoidal transient failed: generalised-alpha rho_infinity full " +
                            std::to_string(result.rho_infinity) + ", reduced " +
                            std::to_string(result.reduced_rho_infinity) + ")\n"
                      : std::string())
              << "  seconds    full " << result.full_seconds << ", reduced "
              << result.reduced_seconds << " (" << result.reduced_integrator << ")\n";
  }
  return 0;
}
} // namespace chipflex::apps
