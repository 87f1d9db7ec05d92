#pragma once
// Shared by the libFuzzer targets: the input written to a temporary file (the readers
// take paths), and the verdict on an exception. A reader may refuse any input with an
// exception that names the problem (InputError, or a std::exception from a library it
// uses); it must never crash, hang, leak or read out of bounds (AddressSanitizer,
// UndefinedBehaviorSanitizer and libFuzzer's own limits catch those).

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

namespace chipflex::fuzz
{
/// A file in /tmp with the input's bytes, removed when it goes out of scope.
class TemporaryInput
{
public:
  TemporaryInput(const std::uint8_t* data, std::size_t size, const std::string& suffix)
      : path_("/tmp/chipflex_fuzz_" + std::to_string(::getpid()) + suffix)
  {
    std::ofstream out(path_, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  ~TemporaryInput() { std::remove(path_.c_str()); }
  TemporaryInput(const TemporaryInput&) = delete;
  TemporaryInput& operator=(const TemporaryInput&) = delete;
  const std::string& path() const { return path_; }

private:
  std::string path_;
};
} // namespace chipflex::fuzz
