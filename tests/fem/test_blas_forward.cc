// The dgemm -> dgemv forwarding (fem/blas_gemv_forward.cc): the forwarded products equal
// the definition of dgemm, and MUMPS's solves really pass through it (the symbol is
// exported from the executable), so the speed-up measured by `chipflex bench reduce` is
// the code under test.

#include "fem/blas_gemv_forward.h"
#include "fem_test_support.h"

#include <catch2/catch.hpp>
#include <limits>
#include <vector>

extern "C" void dgemm_(const char*, const char*, const int*, const int*, const int*, const double*,
                       const double*, const int*, const double*, const int*, const double*, double*,
                       const int*);

using namespace chipflex::fem;
using namespace chipflex::fem::testing;

TEST_CASE("single-column dgemm equals its definition for every transpose case", "[fem]")
{
  const int m = 7, k = 5, lda = 9, ldb = 4;
  std::vector<double> a(lda * 9), b(ldb * 9);
  for (std::size_t i = 0; i < a.size(); ++i)
    a[i] = std::sin(1.0 + i);
  for (std::size_t i = 0; i < b.size(); ++i)
    b[i] = std::cos(2.0 + i);
  for (const char ta : {'N', 'T'})
    for (const char tb : {'N', 'T'})
      for (const double beta : {0.0, 0.5})
      {
        // op(A)(i, l) and op(B)(l, 0) in column-major storage.
        auto op_a = [&](int i, int l) { return ta == 'N' ? a[i + l * lda] : a[l + i * lda]; };
        auto op_b = [&](int l) { return tb == 'N' ? b[l] : b[l * ldb]; };
        // beta = 0 must not read C: start from NaN there.
        const double start = beta == 0 ? std::numeric_limits<double>::quiet_NaN() : 3.0;
        std::vector<double> c(m, start);
        const double alpha = 1.5;
        const int n = 1, ldc = m;
        const long before = forwarded_gemm_calls();
        dgemm_(&ta, &tb, &m, &n, &k, &alpha, a.data(), &lda, b.data(), &ldb, &beta, c.data(), &ldc);
        CHECK(forwarded_gemm_calls() == before + 1);
        for (int i = 0; i < m; ++i)
        {
          double expected = beta == 0 ? 0 : beta * start;
          for (int l = 0; l < k; ++l)
            expected += alpha * op_a(i, l) * op_b(l);
          INFO("transa " << ta << ", transb " << tb << ", beta " << beta << ", row " << i);
          CHECK(c[i] == Approx(expected).epsilon(1e-14).margin(1e-14));
        }
      }
  // k = 0: C = beta C, which dgemm does and dgemv's quick return would not.
  std::vector<double> c(3, 2.0);
  const int three = 3, one = 1, zero = 0;
  const double alpha = 1, beta = 0.25;
  dgemm_("N", "N", &three, &one, &zero, &alpha, a.data(), &three, b.data(), &one, &beta, c.data(),
         &three);
  CHECK(c[0] == 0.5);
}

TEST_CASE("MUMPS's single-vector solves pass through the dgemv forwarding", "[fem]")
{
  ReductionSettings s;
  s.material = {2.1e11, 0.3, 7850, false};
  s.mesh_file = strip_mesh(0.1, 0.004, 0.002, 0.001);
  s.clamp_group = "clamp";
  s.n_modes = 2;
  const long before = forwarded_gemm_calls();
  const auto body = reduce_body(s);
  INFO("forwarded products: " << forwarded_gemm_calls() - before);
  CHECK(forwarded_gemm_calls() > before);
  CHECK(body.frequencies_hz[0] > 0);
}
