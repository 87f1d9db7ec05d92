#include "common/zip_archive.h"

#include "common/atomic_output.h"
#include "common/input_error.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <zlib.h>

namespace chipflex
{
namespace
{
// Record signatures and the one fixed time stamp (MS-DOS date 1980-01-01, 00:00).
constexpr std::uint32_t local_signature = 0x04034b50;
constexpr std::uint32_t central_signature = 0x02014b50;
constexpr std::uint32_t end_signature = 0x06054b50;
constexpr std::uint16_t dos_date = (0 << 9) | (1 << 5) | 1;
constexpr std::uint16_t dos_time = 0;

void put16(std::string& out, std::uint32_t v)
{
  out.push_back(static_cast<char>(v & 0xff));
  out.push_back(static_cast<char>((v >> 8) & 0xff));
}

void put32(std::string& out, std::uint32_t v)
{
  put16(out, v & 0xffff);
  put16(out, v >> 16);
}

std::uint32_t get16(const std::string& in, std::size_t at)
{
  return static_cast<unsigned char>(in[at]) | (static_cast<unsigned char>(in[at + 1]) << 8);
}

std::uint32_t get32(const std::string& in, std::size_t at)
{
  return get16(in, at) | (get16(in, at + 2) << 16);
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

std::string read_file_bytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path, "cannot open the zip archive");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Raw inflate (RFC 1951, no zlib header) of `compressed` into exactly `size` bytes.
std::string inflate_raw(const std::string& compressed, std::size_t size, const std::string& where)
{
  std::string out(size, '\0');
  z_stream z{};
  if (inflateInit2(&z, -MAX_WBITS) != Z_OK)
    throw InputError(where, "zlib cannot start inflating");
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
  z.avail_in = static_cast<uInt>(compressed.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = inflate(&z, Z_FINISH);
  const std::size_t produced = z.total_out;
  inflateEnd(&z);
  if (rc != Z_STREAM_END || produced != size)
    throw InputError(where, "corrupt deflate data");
  return out;
}
} // namespace

unsigned long crc32_of(const std::string& bytes)
{
  return crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(bytes.data()),
               static_cast<uInt>(bytes.size()));
}

void write_zip(const std::string& path, const std::vector<ZipEntry>& entries)
{
  constexpr std::uint64_t limit = std::numeric_limits<std::uint32_t>::max();
  std::string archive, central;
  for (const auto& e : entries)
  {
    if (!safe_name(e.name))
      throw InputError(path, "bad zip entry name '" + e.name + "'");
    if (e.bytes.size() >= limit || archive.size() >= limit || entries.size() >= 0xffff)
      throw InputError(path, "too large for a zip archive without Zip64");
    const std::uint32_t crc = crc32_of(e.bytes), size = static_cast<std::uint32_t>(e.bytes.size());
    const std::uint32_t offset = static_cast<std::uint32_t>(archive.size());
    // local file header: version 2.0, no flags, stored
    put32(archive, local_signature);
    put16(archive, 20);
    put16(archive, 0);
    put16(archive, 0);
    put16(archive, dos_time);
    put16(archive, dos_date);
    put32(archive, crc);
    put32(archive, size);
    put32(archive, size);
    put16(archive, static_cast<std::uint32_t>(e.name.size()));
    put16(archive, 0);
    archive += e.name;
    archive += e.bytes;
    // central directory header: made by Unix (3) v2.0, external attributes rw-r--r--
    put32(central, central_signature);
    put16(central, (3 << 8) | 20);
    put16(central, 20);
    put16(central, 0);
    put16(central, 0);
    put16(central, dos_time);
    put16(central, dos_date);
    put32(central, crc);
    put32(central, size);
    put32(central, size);
    put16(central, static_cast<std::uint32_t>(e.name.size()));
    put16(central, 0);
    put16(central, 0);
    put16(central, 0);
    put16(central, 0);
    put32(central, 0100644u << 16);
    put32(central, offset);
    central += e.name;
  }
  if (archive.size() + central.size() >= limit)
    throw InputError(path, "too large for a zip archive without Zip64");
  const std::uint32_t central_offset = static_cast<std::uint32_t>(archive.size());
  archive += central;
  put32(archive, end_signature);
  put16(archive, 0);
  put16(archive, 0);
  put16(archive, static_cast<std::uint32_t>(entries.size()));
  put16(archive, static_cast<std::uint32_t>(entries.size()));
  put32(archive, static_cast<std::uint32_t>(central.size()));
  put32(archive, central_offset);
  put16(archive, 0);

  AtomicOutput output(path);
  {
    std::ofstream out(output.temporary_path(), std::ios::binary);
    out.write(archive.data(), static_cast<std::streamsize>(archive.size()));
    if (!out)
      throw InputError(path, "cannot write");
  }
  output.commit();
}

std::vector<ZipEntry> read_zip(const std::string& path)
{
  const std::string in = read_file_bytes(path);
  // The end record is the last 22 bytes plus a comment of at most 64 KiB.
  constexpr std::size_t end_size = 22;
  if (in.size() < end_size)
    throw InputError(path, "not a zip archive (too short)");
  std::size_t end = std::string::npos;
  const std::size_t lowest = in.size() > end_size + 0xffff ? in.size() - end_size - 0xffff : 0;
  for (std::size_t at = in.size() - end_size + 1; at-- > lowest;)
    if (get32(in, at) == end_signature)
    {
      end = at;
      break;
    }
  if (end == std::string::npos)
    throw InputError(path, "not a zip archive (no end of central directory record)");
  const std::uint32_t n_entries = get16(in, end + 10);
  const std::uint32_t central_size = get32(in, end + 12);
  std::size_t at = get32(in, end + 16);
  if (get16(in, end + 4) != 0 || at + central_size > end)
    throw InputError(path, "multi-disk, Zip64 or truncated zip archives are not supported");

  std::vector<ZipEntry> entries;
  for (std::uint32_t k = 0; k < n_entries; ++k)
  {
    if (at + 46 > end || get32(in, at) != central_signature)
      throw InputError(path, "corrupt central directory (entry " + std::to_string(k) + ")");
    const std::uint32_t flags = get16(in, at + 8), method = get16(in, at + 10);
    const std::uint32_t crc = get32(in, at + 16), packed = get32(in, at + 20),
                        size = get32(in, at + 24);
    const std::uint32_t name_length = get16(in, at + 28), extra_length = get16(in, at + 30),
                        comment_length = get16(in, at + 32);
    const std::uint32_t local = get32(in, at + 42);
    if (at + 46 + name_length > end)
      throw InputError(path, "corrupt central directory (entry " + std::to_string(k) + ")");
    ZipEntry e;
    e.name = in.substr(at + 46, name_length);
    at += 46 + name_length + extra_length + comment_length;
    const std::string where = path + ": " + e.name;
    if (!e.name.empty() && e.name.back() == '/')
      continue;
    if (flags & 1)
      throw InputError(where, "encrypted zip entries are not supported");
    if (packed == 0xffffffffu || size == 0xffffffffu)
      throw InputError(where, "Zip64 entries are not supported");
    if (local + 30 > in.size() || get32(in, local) != local_signature)
      throw InputError(where, "corrupt local file header");
    const std::size_t data = local + 30 + get16(in, local + 26) + get16(in, local + 28);
    if (data + packed > in.size())
      throw InputError(where, "truncated entry");
    const std::string raw = in.substr(data, packed);
    if (method == 0)
    {
      if (packed != size)
        throw InputError(where, "stored entry with unequal sizes");
      e.bytes = raw;
    }
    else if (method == 8)
      e.bytes = inflate_raw(raw, size, where);
    else
      throw InputError(where, "compression method " + std::to_string(method) +
                                  " is not supported (only stored and deflate)");
    if (crc32_of(e.bytes) != crc)
      throw InputError(where, "CRC-32 mismatch (corrupt archive)");
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
