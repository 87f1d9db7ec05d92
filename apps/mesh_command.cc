#include "apps/commands.h"
#include "common/input_error.h"

namespace chipflex::apps
{
int mesh_command(const Arguments&)
{
  throw InputError("chipflex mesh", "not built yet");
}
} // namespace chipflex::apps
