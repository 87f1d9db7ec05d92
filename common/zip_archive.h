#pragma once
// Zip archives (PKWARE APPNOTE 6.3: local file headers, central directory, end record),
// the container of FMI 2.0 FMUs. Writing stores the entries uncompressed (method 0) with
// their CRC-32, a fixed 1980-01-01 time stamp and in the order given, so the same
// entries always give the same bytes. Reading takes stored (0) and deflated (8) entries,
// the latter through zlib's raw inflate, and checks every entry's CRC-32 and size. No
// Zip64 (entries and archives below 4 GiB), no encryption, no multi-disk archives.

#include <string>
#include <vector>

namespace chipflex
{
struct ZipEntry
{
  std::string name;  ///< path inside the archive, '/' separated, no leading '/'
  std::string bytes; ///< the uncompressed content
};

/// CRC-32 (ISO 3309, the zip and PNG polynomial) of a byte string.
unsigned long crc32_of(const std::string& bytes);

/// Writes the entries as a stored zip archive atomically (temporary file, then rename);
/// throws InputError for a name that is empty, absolute or contains "..", or data too
/// large for a plain zip.
void write_zip(const std::string& path, const std::vector<ZipEntry>& entries);

/// Reads every file entry of a zip archive (folders, i.e. names ending in '/', are left
/// out); throws InputError naming the archive and entry for anything it cannot read.
std::vector<ZipEntry> read_zip(const std::string& path);

/// Unpacks a zip archive into a folder (created with its subfolders); entry names that
/// would leave the folder (absolute, "..") are refused with InputError.
void extract_zip(const std::string& path, const std::string& folder);
} // namespace chipflex
