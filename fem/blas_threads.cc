#include "fem/blas_threads.h"

#include <dlfcn.h>

namespace chipflex::fem
{
bool set_blas_threads(int threads)
{
  using SetThreads = void (*)(int);
  const auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (set == nullptr)
    return false;
  set(threads);
  return true;
}
} // namespace chipflex::fem
