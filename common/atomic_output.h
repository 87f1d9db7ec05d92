#pragma once
// Nothing is written to a final output path until it is complete: write to a temporary
// file beside it, then rename (atomic on POSIX file systems). If the writer throws, the
// destructor removes the temporary and the old file (if any) stays untouched.

#include <string>

namespace chipflex
{
class AtomicOutput
{
public:
  explicit AtomicOutput(std::string final_path);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  /// Where the writer should write (same folder as the final path).
  const std::string& temporary_path() const { return temporary_path_; }
  /// Rename the finished temporary onto the final path.
  void commit();

private:
  std::string final_path_;
  std::string temporary_path_;
  bool committed_ = false;
};
} // namespace chipflex
