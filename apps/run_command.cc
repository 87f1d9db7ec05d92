#include "apps/commands.h"
#include "common/input_error.h"

namespace chipflex::apps
{
int run_command(const Arguments&)
{
  throw InputError("chipflex run", "not built yet");
}
} // namespace chipflex::apps
