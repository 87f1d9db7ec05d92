#pragma once
// DIR/probes.csv: one row per probe interval, `time_s` then one column per gauge
// (p_<name>_Pa, h_<name>_m). Rows are kept in memory and the file is rewritten
// atomically at every flush, so it is never half written; a restart keeps the rows up to
// the restart time.

#include <string>
#include <vector>

namespace chipflex::apps
{
class ProbeOutput
{
public:
  /// `writes` false (MPI ranks other than 0): keeps the rows, writes no file.
  ProbeOutput(std::string path, std::vector<std::string> columns, bool writes = true);
  void resume(double time);
  void add(double time, const std::vector<double>& values);
  void flush() const;
  bool empty() const { return columns_.empty(); }

private:
  std::string path_;
  std::vector<std::string> columns_;
  std::vector<std::string> rows_;
  std::vector<double> row_times_;
  bool writes_;
};
} // namespace chipflex::apps
