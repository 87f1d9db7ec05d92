#include "bench/benchmarks.h"
#include "common/input_error.h"

namespace chipflex::bench
{
int mbs_step_benchmark(const Arguments&)
{
  throw InputError("chipflex bench", "not built yet");
}
} // namespace chipflex::bench
