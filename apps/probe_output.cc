#include "apps/probe_output.h"

#include "common/atomic_output.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace chipflex::apps
{
ProbeOutput::ProbeOutput(std::string path, std::vector<std::string> columns, bool writes)
    : path_(std::move(path)), columns_(std::move(columns)), writes_(writes)
{
}

void ProbeOutput::resume(double time)
{
  rows_.clear();
  row_times_.clear();
  std::ifstream in(path_);
  std::string line;
  if (!std::getline(in, line))
    return;
  while (std::getline(in, line))
  {
    const double t = std::strtod(line.c_str(), nullptr);
    // Rows carry 9 significant digits (add()): the row written at the restart time
    // itself may read up to 5e-10 relative above it, and belongs to the kept history.
    if (t > time * (1 + 1e-8) + 1e-15)
      break;
    rows_.push_back(line);
    row_times_.push_back(t);
  }
}

void ProbeOutput::add(double time, const std::vector<double>& values)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.9g", time);
  std::string row = buffer;
  for (double v : values)
  {
    std::snprintf(buffer, sizeof buffer, ",%.9g", v);
    row += buffer;
  }
  rows_.push_back(row);
  row_times_.push_back(time);
}

void ProbeOutput::flush() const
{
  if (columns_.empty() || !writes_)
    return;
  AtomicOutput out(path_);
  {
    std::ofstream f(out.temporary_path());
    f << "time_s";
    for (const auto& c : columns_)
      f << "," << c;
    f << "\n";
    for (const auto& r : rows_)
      f << r << "\n";
    if (!f)
      throw std::runtime_error("cannot write " + out.temporary_path());
  }
  out.commit();
}
} // namespace chipflex::apps
