#pragma once
// A small RAII wrapper over the HDF5 C API: datasets of doubles and integers of any
// rank (row-major, as HDF5 stores them), scalar and string attributes, groups created
// on demand. Every failure throws InputError naming the file and the object, so a
// corrupted or foreign file gives one clear line instead of HDF5's error stack.
//
// Kept free of deal.II and Eigen so that sph/, mbs/ and fem/ can all use it.

#include <cstdint>
#include <string>
#include <vector>

namespace chipflex
{
class Hdf5File
{
public:
  enum class Mode
  {
    read,
    create, /// truncates
    update  /// an existing file, read and write (e.g. to patch an attribute)
  };
  Hdf5File(const std::string& path, Mode mode);
  ~Hdf5File();
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;

  const std::string& path() const { return path_; }
  bool exists(const std::string& object) const;

  // Datasets. `shape` is the HDF5 (row-major) shape; its product is data.size().
  void write(const std::string& dataset, const std::vector<double>& data,
             const std::vector<std::size_t>& shape);
  void write(const std::string& dataset, const std::vector<std::int64_t>& data,
             const std::vector<std::size_t>& shape);
  void write(const std::string& dataset, const std::vector<std::string>& strings);
  /// Reads a dataset; if `expected_shape` is non-empty the shape must match it exactly.
  std::vector<double> read_doubles(const std::string& dataset,
                                   std::vector<std::size_t>* shape = nullptr) const;
  std::vector<std::int64_t> read_integers(const std::string& dataset,
                                          std::vector<std::size_t>* shape = nullptr) const;
  std::vector<std::string> read_strings(const std::string& dataset) const;

  // Attributes on a group or dataset (created on demand for writing).
  void write_attribute(const std::string& object, const std::string& name, double value);
  void write_attribute(const std::string& object, const std::string& name, std::int64_t value);
  void write_attribute(const std::string& object, const std::string& name,
                       const std::string& value);
  bool has_attribute(const std::string& object, const std::string& name) const;
  double read_double_attribute(const std::string& object, const std::string& name) const;
  std::int64_t read_integer_attribute(const std::string& object, const std::string& name) const;
  std::string read_string_attribute(const std::string& object, const std::string& name) const;

  /// Names of the direct children of a group.
  std::vector<std::string> children(const std::string& group) const;

  /// Creates a group and its parents if missing.
  void ensure_group(const std::string& group);

private:
  [[noreturn]] void fail(const std::string& object, const std::string& problem) const;
  std::int64_t open_object(const std::string& object) const;

  std::string path_;
  std::int64_t file_ = -1;
};
} // namespace chipflex
