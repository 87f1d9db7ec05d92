#include "apps/commands.h"
#include "common/input_error.h"

namespace chipflex::apps
{
int plot_command(const Arguments&)
{
  throw InputError("chipflex plot", "not built yet");
}
} // namespace chipflex::apps
