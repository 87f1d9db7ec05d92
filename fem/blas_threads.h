#pragma once
// The thread count of the BLAS under MUMPS.
//
// Why: Debian's OpenBLAS (pthread build) starts one thread per core, and its threads
// spin while they wait for work. With MPI ranks, deal.II and other processes on the same
// cores, a loaded machine turns that into a stall: `chipflex reduce` of a 3D plate (0.5 mm
// elements, 8 modes) took 422 s wall for 72 s of CPU with two BLAS threads beside a
// two-core build, and 55 s wall for 55 s of CPU with one (docs/performance.md). One BLAS
// thread per process is the default; parallelism comes from MPI ranks (mpirun -np N).

namespace chipflex::fem
{
/// Sets the BLAS library's thread count if it is OpenBLAS (openblas_set_num_threads,
/// looked up at run time: the reference BLAS has no threads). Returns whether it could.
bool set_blas_threads(int threads);
} // namespace chipflex::fem
