#include "common/distributed_hdf5_file.h"

#include "common/input_error.h"

#include <hdf5.h>
#include <mpi.h>
#include <stdexcept>

namespace chipflex
{
namespace
{
/// Closes an HDF5 identifier at the end of the scope.
struct Handle
{
  hid_t id;
  herr_t (*close)(hid_t);
  ~Handle()
  {
    if (id >= 0)
      close(id);
  }
};
} // namespace

DistributedHdf5File::DistributedHdf5File(const std::string& path, std::size_t local_rows)
    : path_(path), local_rows_(local_rows)
{
  unsigned long long mine = local_rows, before = 0, total = 0;
  MPI_Exscan(&mine, &before, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(&mine, &total, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  first_row_ = rank == 0 ? 0 : std::size_t(before); // MPI_Exscan leaves rank 0's undefined
  total_rows_ = std::size_t(total);
  Handle access{H5Pcreate(H5P_FILE_ACCESS), H5Pclose};
  H5Pset_fapl_mpio(access.id, MPI_COMM_WORLD, MPI_INFO_NULL);
  file_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.id);
  if (file_ < 0)
    throw InputError(path, "cannot create file (parallel HDF5)");
}

DistributedHdf5File::~DistributedHdf5File()
{
  if (file_ >= 0)
    H5Fclose(file_);
}

template <typename T>
void DistributedHdf5File::write(const std::string& dataset, const std::vector<T>& data,
                                std::size_t columns, std::int64_t memory_type,
                                std::int64_t file_type)
{
  if (data.size() != local_rows_ * columns)
    throw std::logic_error("DistributedHdf5File::write_rows: " + dataset + " holds " +
                           std::to_string(data.size()) + " values, not rows x columns");
  const int rank = columns > 1 ? 2 : 1;
  const hsize_t whole[2] = {hsize_t(total_rows_), hsize_t(columns)};
  const hsize_t start[2] = {hsize_t(first_row_), 0};
  const hsize_t mine[2] = {hsize_t(local_rows_), hsize_t(columns)};
  Handle file_space{H5Screate_simple(rank, whole, nullptr), H5Sclose};
  Handle set{H5Dcreate2(file_, dataset.c_str(), hid_t(file_type), file_space.id, H5P_DEFAULT,
                        H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose};
  if (set.id < 0)
    throw InputError(path_ + ":" + dataset, "cannot create dataset (parallel HDF5)");
  // A rank without rows still takes part in the collective write, selecting nothing.
  Handle memory_space{H5Screate_simple(rank, mine, nullptr), H5Sclose};
  if (local_rows_ == 0)
  {
    H5Sselect_none(file_space.id);
    H5Sselect_none(memory_space.id);
  }
  else
    H5Sselect_hyperslab(file_space.id, H5S_SELECT_SET, start, nullptr, mine, nullptr);
  Handle transfer{H5Pcreate(H5P_DATASET_XFER), H5Pclose};
  H5Pset_dxpl_mpio(transfer.id, H5FD_MPIO_COLLECTIVE);
  const T none{};
  const herr_t status = H5Dwrite(set.id, hid_t(memory_type), memory_space.id, file_space.id,
                                 transfer.id, data.empty() ? &none : data.data());
  if (status < 0)
    throw InputError(path_ + ":" + dataset, "cannot write dataset (parallel HDF5)");
}

void DistributedHdf5File::write_rows(const std::string& dataset, const std::vector<double>& data,
                                     std::size_t columns)
{
  write(dataset, data, columns, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE);
}

void DistributedHdf5File::write_rows(const std::string& dataset,
                                     const std::vector<std::int64_t>& data, std::size_t columns)
{
  write(dataset, data, columns, H5T_NATIVE_INT64, H5T_STD_I64LE);
}
} // namespace chipflex
