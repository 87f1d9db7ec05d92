#include "apps/commands.h"
#include "common/input_error.h"

namespace chipflex::apps
{
int info_command(const Arguments&)
{
  throw InputError("chipflex info", "not built yet");
}
} // namespace chipflex::apps
