#include "common/atomic_output.h"

#include "common/input_error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>

namespace chipflex
{
AtomicOutput::AtomicOutput(std::string final_path)
    : final_path_(std::move(final_path)),
      temporary_path_(final_path_ + ".tmp" + std::to_string(::getpid()))
{
}

AtomicOutput::~AtomicOutput()
{
  if (!committed_)
    std::remove(temporary_path_.c_str());
}

void AtomicOutput::commit()
{
  if (std::rename(temporary_path_.c_str(), final_path_.c_str()) != 0)
    throw InputError(final_path_, std::string("cannot write: ") + std::strerror(errno));
  committed_ = true;
}
} // namespace chipflex
