#include "apps/commands.h"
#include "common/input_error.h"

namespace chipflex::apps
{
int bench_command(const Arguments&)
{
  throw InputError("chipflex bench", "not built yet");
}
} // namespace chipflex::apps
