// `chipflex reduce MESH.msh -o BODY.h5`: the reduced floating-frame body of a gmsh mesh
// (fem/reduce.h). Runs under `mpirun -np N` too; only rank 0 prints and writes.

#include "apps/commands.h"
#include "common/command_line.h"
#include "common/input_error.h"
#include "common/reduced_body_file.h"
#include "fem/blas_threads.h"
#include "fem/reduce.h"

#include <deal.II/base/mpi.h>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace chipflex::apps
{
namespace
{
/// "pressure:skin,force:tip:0,-1" -> {"pressure:skin", "force:tip:0,-1"}: a new case starts
/// at each item naming a load kind, the other items are force components.
std::vector<std::string> split_load_cases(const std::vector<std::string>& options)
{
  std::vector<std::string> cases;
  for (const auto& option : options)
  {
    std::stringstream items(option);
    std::string item;
    while (std::getline(items, item, ','))
      if (item.rfind("pressure:", 0) == 0 || item.rfind("force:", 0) == 0 || cases.empty())
        cases.push_back(item);
      else
        cases.back() += "," + item;
  }
  return cases;
}

/// PETSc reads its options (e.g. -log_view) from the command line it is initialised with.
std::vector<std::string> petsc_arguments(const std::string& options)
{
  std::vector<std::string> arguments{"chipflex"};
  std::stringstream items(options);
  std::string item;
  while (items >> item)
    arguments.push_back(item);
  return arguments;
}
} // namespace

int reduce_command(const Arguments& args)
{
  common::CommandLine cl(
      "chipflex reduce MESH.msh -o BODY.h5 [options]",
      "Reduce a gmsh mesh to a floating-frame body file (HDF5, format v2): consistent\n"
      "mass and stiffness (deal.II), elastic normal modes (SLEPc Krylov-Schur,\n"
      "shift-and-invert, MUMPS), optional static correction modes, a mass-orthonormal\n"
      "basis and the inertia invariants. Works under mpirun -np N.\n"
      "The material has no defaults: --E, --nu and --rho are required (the elastic\n"
      "gate's rubber, Antoci et al. 2007: --E 1.2e7 --nu 0.4 --rho 1100).");
  cl.add_positional("MESH", "gmsh mesh (.msh) with named physical groups");
  cl.add_option("--output", "FILE", "body file to write (.h5)", "", true);
  cl.add_alias("-o", "--output");
  // No defaults: a forgotten option must not silently give the elastic gate's rubber.
  // fem::Material::check() names a missing one (checked after --help is handled).
  cl.add_option("--E", "PA", "Young's modulus (required)");
  cl.add_option("--nu", "-", "Poisson's ratio, in (-1, 0.5) (required)");
  cl.add_option("--rho", "KG/M3", "density (required)");
  cl.add_flag("--plane-strain", "2D: plane strain (default), per metre of depth");
  cl.add_flag("--plane-stress", "2D: plane stress, per metre of depth");
  cl.add_option("--clamp", "GROUP", "fix this boundary group (cantilever); default free-free");
  cl.add_option("--modes", "N", "number of elastic normal modes", "10");
  cl.add_repeated_option("--static-modes", "LIST",
                         "static correction modes, e.g. pressure:skin,force:tip:0,-1");
  cl.add_flag("--nonlinear",
              "geometrically nonlinear body (St Venant-Kirchhoff): modal derivatives join the "
              "basis, the file gets the reduced internal force as a cubic polynomial");
  cl.add_option("--modal-derivatives", "N",
                "with --nonlinear: derivatives of the first N normal modes, all N(N+1)/2 pairs "
                "(default min(--modes, 5))");
  cl.add_option("--degree", "P", "element degree, 1 or 2", "2");
  cl.add_flag("--straight-sided",
              "ignore a second-order mesh's curved geometry: straight-sided cells through the "
              "corners (to measure the faceting error)");
  cl.add_option("--export-matrices", "DIR",
                "write M and K, clamped DoFs left out (one process; docs/export_matrices.md)");
  cl.add_option("--export-matrices-format", "FORMAT",
                "mtx: M.mtx, K.mtx, dof_nodes.csv; hdf5: matrices.h5 (CSR datasets)", "mtx");
  cl.add_option("--vtu", "FILE", "mode shapes for ParaView (.vtu)");
  cl.add_option("--petsc-options", "'OPTS'", "options for PETSc/SLEPc, e.g. '-log_view'");
  cl.add_option("--blas-threads", "N",
                "OpenBLAS threads per process (more than 1 helps only on an idle machine; "
                "use mpirun -np N for parallelism)",
                "1");
  if (!cl.parse(args))
    return 0;
  if (cl.get_int("--blas-threads") < 1)
    throw InputError("--blas-threads", "must be at least 1");
  fem::set_blas_threads(int(cl.get_int("--blas-threads")));

  fem::ReductionSettings settings;
  settings.mesh_file = cl.get("MESH");
  if (cl.has("--E"))
    settings.material.youngs_modulus = cl.get_double("--E");
  if (cl.has("--nu"))
    settings.material.poisson_ratio = cl.get_double("--nu");
  if (cl.has("--rho"))
    settings.material.density = cl.get_double("--rho");
  if (cl.flag("--plane-strain") && cl.flag("--plane-stress"))
    throw InputError("--plane-stress", "cannot be combined with --plane-strain");
  settings.material.plane_stress = cl.flag("--plane-stress");
  settings.material.check();
  if (cl.has("--clamp"))
    settings.clamp_group = cl.get("--clamp");
  const long modes = cl.get_int("--modes");
  settings.static_modes = split_load_cases(cl.get_all("--static-modes"));
  if (modes < 1)
    throw InputError("--modes", "must be at least 1, got " + std::to_string(modes));
  settings.n_modes = modes;
  settings.nonlinear = cl.flag("--nonlinear");
  if (cl.has("--modal-derivatives"))
  {
    if (!settings.nonlinear)
      throw InputError("--modal-derivatives", "needs --nonlinear");
    const long n = cl.get_int("--modal-derivatives");
    if (n < 1 || n > modes)
      throw InputError("--modal-derivatives", "must lie in 1..--modes (" + std::to_string(modes) +
                                                  "), got " + std::to_string(n));
    settings.derivative_modes = n;
  }
  const long degree = cl.get_int("--degree");
  if (degree != 1 && degree != 2)
    throw InputError("--degree", "must be 1 or 2, got " + std::to_string(degree));
  settings.degree = degree;
  settings.straight_sided = cl.flag("--straight-sided");
  if (cl.has("--export-matrices"))
    settings.export_directory = cl.get("--export-matrices");
  settings.export_format = cl.get("--export-matrices-format");
  if (settings.export_format != "mtx" && settings.export_format != "hdf5")
    throw InputError("--export-matrices-format",
                     "expected mtx or hdf5, got '" + settings.export_format + "'");
  if (cl.has("--vtu"))
    settings.vtu_file = cl.get("--vtu");
  const std::string output = cl.get("--output");

  auto arguments = petsc_arguments(cl.has("--petsc-options") ? cl.get("--petsc-options") : "");
  std::vector<char*> argv;
  for (auto& a : arguments)
    argv.push_back(a.data());
  int argc = argv.size();
  char** argv_pointer = argv.data();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv_pointer, 1);
  const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  fem::ReductionTimings timings;
  const ReducedBodyData body = fem::reduce_body(settings, &timings);
  if (root)
  {
    write_reduced_body(output, body);
    std::cout << "wrote " << output << ": " << body.dim << "D, " << body.n_nodes() << " nodes, "
              << timings.n_dofs << " DoFs, "
              << (body.clamp_set.empty() ? "free-free" : "clamped at '" + body.clamp_set + "'")
              << ", mass " << body.mass << " kg" << (body.dim == 2 ? "/m" : "") << ", "
              << (body.nonlinear()
                      ? "nonlinear (St Venant-Kirchhoff, " +
                            std::to_string(body.n_modal_derivatives) + " modal derivatives)"
                      : std::string("linear"))
              << "\n";
    for (int k = 0; k < body.n_modes(); ++k)
      std::cout << "  mode " << std::setw(2) << k + 1 << "  " << std::setw(12)
                << std::setprecision(6) << body.frequencies_hz[k] << " Hz  " << body.mode_kinds[k]
                << "\n";
    std::cout << std::setprecision(3) << "seconds: mesh " << timings.mesh_reading << ", setup "
              << timings.setup << ", assembly " << timings.assembly << ", factorisation "
              << timings.factorisation << ", eigen solve " << timings.eigen_solve
              << ", static modes " << timings.static_modes << ", basis " << timings.basis
              << ", invariants " << timings.post_processing;
    if (body.nonlinear())
      std::cout << " (of which nonlinear coefficients " << timings.nonlinear << ")";
    std::cout << "\n";
  }
  return 0;
}
} // namespace chipflex::apps
