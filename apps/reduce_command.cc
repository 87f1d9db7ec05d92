#include "apps/commands.h"
#include "common/input_error.h"

namespace chipflex::apps
{
int reduce_command(const Arguments&)
{
  throw InputError("chipflex reduce", "not built yet");
}
} // namespace chipflex::apps
