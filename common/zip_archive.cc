#include "common/zip_archive.h"

#include "common/atomic_output.h"
#include "common/input_error.h"

#include <filesystem>
#include <fstream>
#include <memory>
#include <zip.h>

namespace chipflex
{
namespace
{
// The one time stamp, 1980-01-01 00:00, given as MS-DOS date and time fields: libzip
// would turn a time_t into them through the local time zone, and the bytes with it.
constexpr zip_uint16_t dos_date = (0 << 9) | (1 << 5) | 1;
constexpr zip_uint16_t dos_time = 0;
constexpr zip_uint32_t unix_rw_r__r__ = 0100644u << 16;

/// An archive libzip holds open; dropped without writing anything unless closed.
using Archive = std::unique_ptr<zip_t, decltype(&zip_discard)>;
using EntryFile = std::unique_ptr<zip_file_t, decltype(&zip_fclose)>;

Archive open_archive(const std::string& path, int flags)
{
  int code = 0;
  zip_t* archive = zip_open(path.c_str(), flags, &code);
  if (!archive)
  {
    zip_error_t error;
    zip_error_init_with_code(&error, code);
    const std::string text = zip_error_strerror(&error);
    zip_error_fini(&error);
    throw InputError(path, "cannot open the zip archive: " + text);
  }
  return Archive(archive, &zip_discard);
}

/// A name that stays inside the folder it is unpacked into.
bool safe_name(const std::string& name)
{
  if (name.empty() || name[0] == '/' || name.find('\\') != std::string::npos)
    return false;
  for (const auto& part : std::filesystem::path(name))
    if (part == "..")
      return false;
  return true;
}

/// The whole entry, read to its end: libzip checks the CRC-32 only once it gets there.
std::string read_entry(zip_t* archive, zip_uint64_t index, const std::string& where)
{
  const EntryFile file(zip_fopen_index(archive, index, 0), &zip_fclose);
  if (!file)
    throw InputError(where, std::string("cannot open the entry: ") + zip_strerror(archive));
  std::string bytes;
  char buffer[1 << 16];
  for (zip_int64_t n; (n = zip_fread(file.get(), buffer, sizeof buffer)) != 0;)
  {
    if (n < 0)
    {
      zip_error_t* error = zip_file_get_error(file.get());
      throw InputError(where, zip_error_code_zip(error) == ZIP_ER_CRC
                                  ? std::string("CRC-32 mismatch (corrupt archive)")
                                  : std::string("cannot read: ") + zip_error_strerror(error));
    }
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
  return bytes;
}
} // namespace

void write_zip(const std::string& path, const std::vector<ZipEntry>& entries)
{
  // libzip writes no file at all for an archive without entries.
  if (entries.empty())
    throw InputError(path, "a zip archive needs at least one entry");
  AtomicOutput output(path);
  Archive archive = open_archive(output.temporary_path(), ZIP_CREATE | ZIP_TRUNCATE);
  zip_t* z = archive.get();
  for (const auto& e : entries)
  {
    if (!safe_name(e.name))
      throw InputError(path, "bad zip entry name '" + e.name + "'");
    // The source only points at e.bytes, which outlives zip_close below.
    zip_source_t* source = zip_source_buffer(z, e.bytes.data(), e.bytes.size(), 0);
    const zip_int64_t index =
        source ? zip_file_add(z, e.name.c_str(), source, ZIP_FL_ENC_UTF_8) : -1;
    if (index < 0)
    {
      zip_source_free(source);
      throw InputError(path, "cannot add '" + e.name + "': " + zip_strerror(z));
    }
    const auto i = static_cast<zip_uint64_t>(index);
    if (zip_set_file_compression(z, i, ZIP_CM_STORE, 0) != 0 ||
        zip_file_set_dostime(z, i, dos_time, dos_date, 0) != 0 ||
        zip_file_set_external_attributes(z, i, 0, ZIP_OPSYS_UNIX, unix_rw_r__r__) != 0)
      throw InputError(path, "cannot set up '" + e.name + "': " + zip_strerror(z));
  }
  if (zip_close(z) != 0)
    throw InputError(path, std::string("cannot write the zip archive: ") + zip_strerror(z));
  archive.release(); // zip_close freed it
  output.commit();
}

std::vector<ZipEntry> read_zip(const std::string& path)
{
  const Archive archive = open_archive(path, ZIP_RDONLY | ZIP_CHECKCONS);
  std::vector<ZipEntry> entries;
  const zip_int64_t n = zip_get_num_entries(archive.get(), 0);
  for (zip_int64_t k = 0; k < n; ++k)
  {
    const auto index = static_cast<zip_uint64_t>(k);
    const char* name = zip_get_name(archive.get(), index, 0);
    if (!name)
      throw InputError(path, "entry " + std::to_string(k) + ": " + zip_strerror(archive.get()));
    ZipEntry e{name, {}};
    if (!e.name.empty() && e.name.back() == '/')
      continue;
    e.bytes = read_entry(archive.get(), index, path + ": " + e.name);
    entries.push_back(std::move(e));
  }
  return entries;
}

void extract_zip(const std::string& path, const std::string& folder)
{
  for (const auto& e : read_zip(path))
  {
    if (!safe_name(e.name))
      throw InputError(path + ": " + e.name, "entry name leaves the unpack folder");
    const std::filesystem::path target = std::filesystem::path(folder) / e.name;
    std::filesystem::create_directories(target.parent_path());
    std::ofstream out(target, std::ios::binary);
    out.write(e.bytes.data(), static_cast<std::streamsize>(e.bytes.size()));
    if (!out)
      throw InputError(target.string(), "cannot write");
  }
}
} // namespace chipflex
