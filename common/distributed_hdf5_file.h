#pragma once
// DistributedHdf5File: one HDF5 file that every MPI rank writes together through parallel
// HDF5 (the MPI-IO driver on MPI_COMM_WORLD, collective transfers), each rank its own
// rows of every dataset: rank r's rows follow those of ranks 0 .. r-1. The particle
// frames of a run under mpirun are written this way (apps/particle_output.h), so no rank
// ever holds the whole fluid for a frame.
//
// Every call is collective: all ranks make the same calls in the same order. A failure
// throws InputError naming the file and the dataset. The header stays free of mpi.h and
// hdf5.h; the library is apart from chipflex_common, which the FMU's shared library
// links without MPI.

#include <cstdint>
#include <string>
#include <vector>

namespace chipflex
{
class DistributedHdf5File
{
public:
  /// Creates (truncates) `path`; this rank will write `local_rows` rows of each dataset.
  DistributedHdf5File(const std::string& path, std::size_t local_rows);
  ~DistributedHdf5File();
  DistributedHdf5File(const DistributedHdf5File&) = delete;
  DistributedHdf5File& operator=(const DistributedHdf5File&) = delete;

  /// The rows of all ranks together.
  std::size_t rows() const { return total_rows_; }
  /// Where this rank's rows start.
  std::size_t first_row() const { return first_row_; }

  /// A dataset of rows() x `columns` (one-dimensional for 1 column); `data` holds this
  /// rank's local_rows x columns values, row-major.
  void write_rows(const std::string& dataset, const std::vector<double>& data, std::size_t columns);
  void write_rows(const std::string& dataset, const std::vector<std::int64_t>& data,
                  std::size_t columns);

private:
  template <typename T>
  void write(const std::string& dataset, const std::vector<T>& data, std::size_t columns,
             std::int64_t memory_type, std::int64_t file_type);

  std::string path_;
  std::int64_t file_ = -1;
  std::size_t local_rows_ = 0, first_row_ = 0, total_rows_ = 0;
};
} // namespace chipflex
