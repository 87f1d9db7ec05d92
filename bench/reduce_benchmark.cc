// `chipflex bench reduce`: the reduction of a ~350k-DOF quadratic 3D cantilever strip to
// 20 modes, timed stage by stage (mesh reading, assembly, factorisation, eigen solve,
// writing) with the peak memory. Prints figures; it never passes or fails on time.
// Under `mpirun -np N chipflex bench reduce` the figures are rank 0's (peak memory: per process).

#include "bench/benchmarks.h"
#include "common/input_error.h"
#include "common/reduced_body_file.h"
#include "fem/reduce.h"
#include "meshes/block_mesher.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <deal.II/base/mpi.h>
#include <iomanip>
#include <iostream>
#include <sys/resource.h>
#include <unistd.h>

namespace chipflex::bench
{
int reduce_benchmark(const Arguments& args)
{
  // Strip 0.24 x 0.013 x 0.004 m, hexahedra of 1 mm: 240 x 13 x 4 cells, quadratic:
  // 481 x 27 x 9 nodes = 350,649 DoFs (349,920 after the clamp).
  double size = 0.001;
  unsigned int modes = 20;
  std::string petsc_options;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    auto value = [&]() -> std::string
    {
      if (i + 1 >= args.size())
        throw InputError(args[i], "needs a value");
      return args[++i];
    };
    if (args[i] == "--size")
      size = std::stod(value());
    else if (args[i] == "--modes")
      modes = std::stoul(value());
    else if (args[i] == "--petsc-options")
      petsc_options = value();
    else if (args[i] == "--help")
    {
      std::cout << "chipflex bench reduce [--size M (0.001)] [--modes N (20)] "
                   "[--petsc-options '-log_view']\n";
      return 0;
    }
    else
      throw InputError(args[i], "unknown option of chipflex bench reduce");
  }
  std::vector<std::string> arguments{"chipflex"};
  for (std::size_t p = 0, q; p < petsc_options.size(); p = q + 1)
  {
    q = petsc_options.find(' ', p);
    if (q == std::string::npos)
      q = petsc_options.size();
    if (q > p)
      arguments.push_back(petsc_options.substr(p, q - p));
  }
  std::vector<char*> argv;
  for (auto& a : arguments)
    argv.push_back(a.data());
  int argc = argv.size();
  argv.push_back(nullptr); // argv[argc] == nullptr, as MPI_Init expects
  char** argv_pointer = argv.data();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv_pointer, 1);
  const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);

  // Every rank reads the mesh rank 0 writes, so the name carries rank 0's process id.
  int pid = ::getpid();
  MPI_Bcast(&pid, 1, MPI_INT, 0, MPI_COMM_WORLD);
  const std::string stem = "chipflex_bench_reduce_" + std::to_string(pid);
  const std::string mesh = stem + ".msh", body_file = stem + ".h5";
  // Removed however the benchmark ends (a failed reduction throws past the clean-up).
  struct RemoveOnExit
  {
    std::vector<std::string> paths;
    bool owner;
    ~RemoveOnExit()
    {
      if (owner)
        for (const auto& p : paths)
          std::remove(p.c_str());
    }
  } scratch_files{{mesh, body_file}, rank == 0};
  using clock = std::chrono::steady_clock;
  auto t0 = clock::now();
  if (rank == 0)
  {
    meshes::BlockMeshSpec spec;
    spec.dim = 3;
    spec.extent = {0.24, 0.013, 0.004};
    spec.long_axis = 0;
    spec.clamp_at_max = false;
    spec.size = size;
    meshes::write_block_mesh(spec, mesh);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  const double meshing = std::chrono::duration<double>(clock::now() - t0).count();

  fem::ReductionSettings settings;
  settings.mesh_file = mesh;
  settings.material = {2.1e11, 0.3, 7850, false};
  settings.clamp_group = "clamp";
  settings.n_modes = modes;
  fem::ReductionTimings timings;
  // CPU seconds as well as wall seconds: on a shared machine the wall time also measures
  // the other jobs.
  auto cpu_seconds = []
  {
    struct rusage u;
    getrusage(RUSAGE_SELF, &u);
    return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  };
  double load[1] = {0};
  getloadavg(load, 1);
  const double cpu0 = cpu_seconds();
  t0 = clock::now();
  const ReducedBodyData body = fem::reduce_body(settings, &timings);
  const double reduction = std::chrono::duration<double>(clock::now() - t0).count();
  t0 = clock::now();
  if (rank == 0)
    write_reduced_body(body_file, body);
  const double writing = std::chrono::duration<double>(clock::now() - t0).count();
  const double cpu = cpu_seconds() - cpu0;
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  if (rank == 0)
  {
    std::cout << std::fixed << std::setprecision(2)
              << "reduce benchmark: 3D strip 0.24 x 0.013 x 0.004 m, quadratic hexahedra, "
              << timings.n_cells << " cells, " << timings.n_dofs << " DoFs, " << modes << " modes, "
              << n_ranks << " MPI process(es)\n"
              << "  meshing (gmsh, not part of the reduction) " << meshing << " s\n"
              << "  mesh reading          " << timings.mesh_reading << " s\n"
              << "  setup (DoFs, sets)    " << timings.setup << " s\n"
              << "  assembly (K, M, Ms)   " << timings.assembly << " s\n"
              << "  factorisation (MUMPS) " << timings.factorisation << " s\n"
              << "  eigen solve (SLEPc)   " << timings.eigen_solve << " s\n"
              << "  basis and invariants  " << timings.basis + timings.post_processing << " s\n"
              << "  writing (HDF5)        " << writing << " s\n"
              << "  reduction total       " << reduction + writing << " s\n"
              << "  CPU time (all threads) " << cpu << " s; load average at start " << load[0]
              << " on " << sysconf(_SC_NPROCESSORS_ONLN) << " cores\n"
              << "  peak memory           " << usage.ru_maxrss / 1024.0 << " MiB (rank 0)\n"
              << std::setprecision(4) << "  f1 = " << body.frequencies_hz[0] << " Hz, f" << modes
              << " = " << body.frequencies_hz[modes - 1] << " Hz\n";
  }
  return 0;
}
} // namespace chipflex::bench
