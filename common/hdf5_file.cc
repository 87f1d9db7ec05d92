#include "common/hdf5_file.h"

#include "common/input_error.h"

#include <hdf5.h>

namespace chipflex
{
namespace
{
/// HDF5 prints its own error stack by default; we report errors ourselves.
void silence_hdf5()
{
  static const bool silenced = []
  {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)silenced;
}

/// Closes any HDF5 identifier on scope exit.
struct Handle
{
  hid_t id;
  explicit Handle(hid_t i) : id(i) {}
  ~Handle()
  {
    if (id >= 0)
      H5Oclose(id);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
};

struct Space
{
  hid_t id;
  explicit Space(hid_t i) : id(i) {}
  ~Space()
  {
    if (id >= 0)
      H5Sclose(id);
  }
};

struct Attribute
{
  hid_t id;
  explicit Attribute(hid_t i) : id(i) {}
  ~Attribute()
  {
    if (id >= 0)
      H5Aclose(id);
  }
};

struct Type
{
  hid_t id;
  explicit Type(hid_t i) : id(i) {}
  ~Type()
  {
    if (id >= 0)
      H5Tclose(id);
  }
};

std::string parent_of(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  return (slash == std::string::npos || slash == 0) ? std::string("/") : path.substr(0, slash);
}
} // namespace

Hdf5File::Hdf5File(const std::string& path, Mode mode) : path_(path)
{
  silence_hdf5();
  if (mode != Mode::create)
  {
    if (H5Fis_hdf5(path.c_str()) <= 0)
      throw InputError(path, "not a readable HDF5 file (missing, truncated or corrupted)");
    file_ = H5Fopen(path.c_str(), mode == Mode::read ? H5F_ACC_RDONLY : H5F_ACC_RDWR, H5P_DEFAULT);
  }
  else
    file_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0)
    throw InputError(path, mode == Mode::create ? "cannot create file" : "cannot open HDF5 file");
}

Hdf5File::~Hdf5File()
{
  if (file_ >= 0)
    H5Fclose(file_);
}

void Hdf5File::fail(const std::string& object, const std::string& problem) const
{
  throw InputError(path_ + ":" + object, problem);
}

bool Hdf5File::exists(const std::string& object) const
{
  if (object == "/")
    return true;
  // Walk the path: H5Lexists fails if an intermediate group is missing.
  std::size_t pos = 0;
  while ((pos = object.find('/', pos + 1)) != std::string::npos)
    if (H5Lexists(file_, object.substr(0, pos).c_str(), H5P_DEFAULT) <= 0)
      return false;
  return H5Lexists(file_, object.c_str(), H5P_DEFAULT) > 0;
}

void Hdf5File::ensure_group(const std::string& group)
{
  if (exists(group))
    return;
  ensure_group(parent_of(group));
  const hid_t g = H5Gcreate2(file_, group.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (g < 0)
    fail(group, "cannot create group");
  H5Gclose(g);
}

std::int64_t Hdf5File::open_object(const std::string& object) const
{
  if (!exists(object))
    fail(object, "missing");
  const hid_t id = H5Oopen(file_, object.c_str(), H5P_DEFAULT);
  if (id < 0)
    fail(object, "cannot open");
  return id;
}

namespace
{
template <typename T>
void write_dataset(hid_t file, const std::string& name, hid_t mem_type, hid_t file_type,
                   const std::vector<T>& data, const std::vector<std::size_t>& shape,
                   const std::string& path)
{
  std::vector<hsize_t> dims(shape.begin(), shape.end());
  std::size_t n = 1;
  for (auto d : shape)
    n *= d;
  if (n != data.size())
    throw std::logic_error("Hdf5File::write: shape does not match data size for " + name);
  Space space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr));
  const hid_t set =
      H5Dcreate2(file, name.c_str(), file_type, space.id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (set < 0)
    throw InputError(path + ":" + name, "cannot create dataset");
  const herr_t status =
      n == 0 ? 0 : H5Dwrite(set, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
  H5Dclose(set);
  if (status < 0)
    throw InputError(path + ":" + name, "cannot write dataset");
}

template <typename T>
std::vector<T> read_dataset(hid_t file, const std::string& name, hid_t mem_type,
                            std::vector<std::size_t>* shape, const std::string& path)
{
  const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  if (set < 0)
    throw InputError(path + ":" + name, "missing dataset");
  Space space(H5Dget_space(set));
  const int rank = H5Sget_simple_extent_ndims(space.id);
  std::vector<hsize_t> dims(rank > 0 ? rank : 0);
  if (rank > 0)
    H5Sget_simple_extent_dims(space.id, dims.data(), nullptr);
  std::size_t n = 1;
  for (auto d : dims)
    n *= d;
  std::vector<T> data(n);
  const herr_t status =
      n == 0 ? 0 : H5Dread(set, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
  H5Dclose(set);
  if (status < 0)
    throw InputError(path + ":" + name, "cannot read dataset (wrong type or corrupted)");
  if (shape)
    shape->assign(dims.begin(), dims.end());
  return data;
}
} // namespace

void Hdf5File::write(const std::string& dataset, const std::vector<double>& data,
                     const std::vector<std::size_t>& shape)
{
  ensure_group(parent_of(dataset));
  write_dataset(file_, dataset, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, data, shape, path_);
}

void Hdf5File::write(const std::string& dataset, const std::vector<std::int64_t>& data,
                     const std::vector<std::size_t>& shape)
{
  ensure_group(parent_of(dataset));
  write_dataset(file_, dataset, H5T_NATIVE_INT64, H5T_STD_I64LE, data, shape, path_);
}

void Hdf5File::write(const std::string& dataset, const std::vector<std::string>& strings)
{
  ensure_group(parent_of(dataset));
  Type type(H5Tcopy(H5T_C_S1));
  H5Tset_size(type.id, H5T_VARIABLE);
  hsize_t n = strings.size();
  Space space(H5Screate_simple(1, &n, nullptr));
  const hid_t set =
      H5Dcreate2(file_, dataset.c_str(), type.id, space.id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (set < 0)
    fail(dataset, "cannot create dataset");
  std::vector<const char*> pointers;
  for (const auto& s : strings)
    pointers.push_back(s.c_str());
  const herr_t status =
      n == 0 ? 0 : H5Dwrite(set, type.id, H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data());
  H5Dclose(set);
  if (status < 0)
    fail(dataset, "cannot write dataset");
}

std::vector<double> Hdf5File::read_doubles(const std::string& dataset,
                                           std::vector<std::size_t>* shape) const
{
  if (!exists(dataset))
    fail(dataset, "missing dataset");
  return read_dataset<double>(file_, dataset, H5T_NATIVE_DOUBLE, shape, path_);
}

std::vector<std::int64_t> Hdf5File::read_integers(const std::string& dataset,
                                                  std::vector<std::size_t>* shape) const
{
  if (!exists(dataset))
    fail(dataset, "missing dataset");
  return read_dataset<std::int64_t>(file_, dataset, H5T_NATIVE_INT64, shape, path_);
}

std::vector<std::string> Hdf5File::read_strings(const std::string& dataset) const
{
  if (!exists(dataset))
    fail(dataset, "missing dataset");
  const hid_t set = H5Dopen2(file_, dataset.c_str(), H5P_DEFAULT);
  if (set < 0)
    fail(dataset, "cannot open dataset");
  Type type(H5Tcopy(H5T_C_S1));
  H5Tset_size(type.id, H5T_VARIABLE);
  Space space(H5Dget_space(set));
  hsize_t n = 0;
  if (H5Sget_simple_extent_ndims(space.id) != 1)
  {
    H5Dclose(set);
    fail(dataset, "expected a 1-D list of strings");
  }
  H5Sget_simple_extent_dims(space.id, &n, nullptr);
  std::vector<char*> pointers(n, nullptr);
  const herr_t status =
      n == 0 ? 0 : H5Dread(set, type.id, H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data());
  std::vector<std::string> result;
  if (status >= 0)
    for (char* p : pointers)
      result.emplace_back(p ? p : "");
  if (n > 0 && status >= 0)
    H5Dvlen_reclaim(type.id, space.id, H5P_DEFAULT, pointers.data());
  H5Dclose(set);
  if (status < 0)
    fail(dataset, "cannot read strings (wrong type or corrupted)");
  return result;
}

namespace
{
hid_t create_attribute(hid_t object, const std::string& name, hid_t type)
{
  if (H5Aexists(object, name.c_str()) > 0)
    H5Adelete(object, name.c_str());
  Space space(H5Screate(H5S_SCALAR));
  return H5Acreate2(object, name.c_str(), type, space.id, H5P_DEFAULT, H5P_DEFAULT);
}
} // namespace

void Hdf5File::write_attribute(const std::string& object, const std::string& name, double value)
{
  ensure_group(object == "/" ? "/" : object);
  Handle o(open_object(object));
  Attribute a(create_attribute(o.id, name, H5T_IEEE_F64LE));
  if (a.id < 0 || H5Awrite(a.id, H5T_NATIVE_DOUBLE, &value) < 0)
    fail(object + "@" + name, "cannot write attribute");
}

void Hdf5File::write_attribute(const std::string& object, const std::string& name,
                               std::int64_t value)
{
  ensure_group(object == "/" ? "/" : object);
  Handle o(open_object(object));
  Attribute a(create_attribute(o.id, name, H5T_STD_I64LE));
  if (a.id < 0 || H5Awrite(a.id, H5T_NATIVE_INT64, &value) < 0)
    fail(object + "@" + name, "cannot write attribute");
}

void Hdf5File::write_attribute(const std::string& object, const std::string& name,
                               const std::string& value)
{
  ensure_group(object == "/" ? "/" : object);
  Handle o(open_object(object));
  Type type(H5Tcopy(H5T_C_S1));
  H5Tset_size(type.id, value.size() + 1);
  H5Tset_strpad(type.id, H5T_STR_NULLTERM);
  Attribute a(create_attribute(o.id, name, type.id));
  if (a.id < 0 || H5Awrite(a.id, type.id, value.c_str()) < 0)
    fail(object + "@" + name, "cannot write attribute");
}

namespace
{
hid_t open_attribute(hid_t object, const std::string& name)
{
  if (H5Aexists(object, name.c_str()) <= 0)
    return -1;
  return H5Aopen(object, name.c_str(), H5P_DEFAULT);
}
} // namespace

bool Hdf5File::has_attribute(const std::string& object, const std::string& name) const
{
  Handle o(open_object(object));
  return H5Aexists(o.id, name.c_str()) > 0;
}

double Hdf5File::read_double_attribute(const std::string& object, const std::string& name) const
{
  Handle o(open_object(object));
  Attribute a(open_attribute(o.id, name));
  double value = 0;
  if (a.id < 0)
    fail(object + "@" + name, "missing attribute");
  if (H5Aread(a.id, H5T_NATIVE_DOUBLE, &value) < 0)
    fail(object + "@" + name, "not a number");
  return value;
}

std::int64_t Hdf5File::read_integer_attribute(const std::string& object,
                                              const std::string& name) const
{
  Handle o(open_object(object));
  Attribute a(open_attribute(o.id, name));
  std::int64_t value = 0;
  if (a.id < 0)
    fail(object + "@" + name, "missing attribute");
  if (H5Aread(a.id, H5T_NATIVE_INT64, &value) < 0)
    fail(object + "@" + name, "not an integer");
  return value;
}

std::string Hdf5File::read_string_attribute(const std::string& object,
                                            const std::string& name) const
{
  Handle o(open_object(object));
  Attribute a(open_attribute(o.id, name));
  if (a.id < 0)
    fail(object + "@" + name, "missing attribute");
  Type stored(H5Aget_type(a.id));
  if (H5Tget_class(stored.id) != H5T_STRING || H5Tis_variable_str(stored.id) > 0)
    fail(object + "@" + name, "not a fixed-length string");
  const std::size_t size = H5Tget_size(stored.id);
  std::string value(size, '\0');
  if (H5Aread(a.id, stored.id, value.data()) < 0)
    fail(object + "@" + name, "cannot read attribute");
  value.resize(value.find('\0') == std::string::npos ? size : value.find('\0'));
  return value;
}

std::vector<std::string> Hdf5File::children(const std::string& group) const
{
  Handle g(open_object(group));
  H5G_info_t info;
  if (H5Gget_info(g.id, &info) < 0)
    fail(group, "not a group");
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i)
  {
    const ssize_t len =
        H5Lget_name_by_idx(g.id, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    std::string name(static_cast<std::size_t>(len), '\0');
    H5Lget_name_by_idx(g.id, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), len + 1, H5P_DEFAULT);
    names.push_back(name);
  }
  return names;
}
} // namespace chipflex
