#include "apps/commands.h"
#include "common/input_error.h"

namespace chipflex::apps
{
int compare_command(const Arguments&)
{
  throw InputError("chipflex compare", "not built yet");
}
} // namespace chipflex::apps
