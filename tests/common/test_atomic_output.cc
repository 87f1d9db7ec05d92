// Outputs appear only when complete: a writer that fails leaves no file behind and
// does not touch an existing one.

#include "common/atomic_output.h"

#include <catch2/catch.hpp>
#include <fstream>
#include <stdexcept>
#include <sys/stat.h>

namespace
{
bool exists(const std::string& p)
{
  struct stat s;
  return ::stat(p.c_str(), &s) == 0;
}
} // namespace

TEST_CASE("atomic output: nothing at the final path until commit", "[common]")
{
  std::remove("atomic.txt");
  {
    chipflex::AtomicOutput out("atomic.txt");
    std::ofstream(out.temporary_path()) << "partial";
    CHECK_FALSE(exists("atomic.txt"));
    out.commit();
  }
  CHECK(exists("atomic.txt"));
  try
  {
    chipflex::AtomicOutput out("atomic.txt");
    std::ofstream(out.temporary_path()) << "second, failing writer";
    throw std::runtime_error("writer failed");
  }
  catch (const std::runtime_error&)
  {
  }
  std::ifstream in("atomic.txt");
  std::string content;
  in >> content;
  CHECK(content == "partial");
  std::remove("atomic.txt");
}
