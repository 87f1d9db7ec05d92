#pragma once
// See fem/blas_gemv_forward.cc: matrix-vector products that MUMPS issues as dgemm with
// one right-hand side are sent to dgemv.

namespace chipflex::fem
{
/// How many dgemm calls with a single column were forwarded to dgemv in this process
/// (0 when the forwarding object is not linked in or not exported).
long forwarded_gemm_calls();
} // namespace chipflex::fem
