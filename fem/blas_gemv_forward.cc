// dgemm with a single column, forwarded to dgemv.
//
// Why: MUMPS's solve phase multiplies each front's factor panel by the right-hand side
// with dgemm, also when there is only one right-hand side (SLEPc's shift-and-invert solves
// one vector at a time). OpenBLAS before 0.3.27 (Debian 12 ships 0.3.21) packs the whole
// panel into a buffer before every such product, which triples the memory traffic of a
// solve that is memory-bound anyway: perf showed dgemm's copy routines taking 35 % of
// `chipflex bench reduce`. dgemv reads the panel once. OpenBLAS 0.3.27 added the same
// forwarding (GEMM_GEMV_FORWARD); this file gives it to older BLAS builds. The results are
// the same operation, C = alpha op(A) op(B) + beta C with C one column: y = alpha op(A) x +
// beta y, beta = 0 not reading C in either routine.
//
// How: this definition of the Fortran symbol dgemm_ is linked into the executables and
// exported (CMake: LINKER:--export-dynamic-symbol=dgemm_), so the dynamic linker binds
// MUMPS's calls to it; every other call goes on to the BLAS library's dgemm_ (dlsym
// RTLD_NEXT). The hidden Fortran string-length arguments are not needed: only the first
// character of each flag is read, as in the reference BLAS.

#include "fem/blas_gemv_forward.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <dlfcn.h>

namespace
{
using Gemm = void (*)(const char*, const char*, const int*, const int*, const int*, const double*,
                      const double*, const int*, const double*, const int*, const double*, double*,
                      const int*);

std::atomic<long> forwarded{0};

Gemm library_gemm()
{
  static const Gemm gemm = []
  {
    auto next = reinterpret_cast<Gemm>(dlsym(RTLD_NEXT, "dgemm_"));
    if (!next)
    {
      std::fprintf(stderr, "chipflex: no BLAS dgemm_ found after the forwarding wrapper\n");
      std::abort();
    }
    return next;
  }();
  return gemm;
}

bool is_no_transpose(const char* flag)
{
  return *flag == 'N' || *flag == 'n';
}
} // namespace

extern "C"
{
  void dgemv_(const char* trans, const int* m, const int* n, const double* alpha, const double* a,
              const int* lda, const double* x, const int* incx, const double* beta, double* y,
              const int* incy);

  void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
              const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
              const double* beta, double* c, const int* ldc)
  {
    // k = 0 must still scale C by beta, which dgemv's quick return would skip.
    if (*n != 1 || *m <= 0 || *k <= 0)
    {
      library_gemm()(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
      return;
    }
    forwarded.fetch_add(1, std::memory_order_relaxed);
    // op(B) is k x 1: a column of B (stride 1) or a row of B (stride ldb).
    const int increment_b = is_no_transpose(transb) ? 1 : *ldb, one = 1;
    if (is_no_transpose(transa)) // A is m x k
      dgemv_("N", m, k, alpha, a, lda, b, &increment_b, beta, c, &one);
    else // A is k x m
      dgemv_("T", k, m, alpha, a, lda, b, &increment_b, beta, c, &one);
  }
}

namespace chipflex::fem
{
long forwarded_gemm_calls()
{
  return forwarded.load();
}
} // namespace chipflex::fem
