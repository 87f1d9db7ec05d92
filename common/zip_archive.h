#pragma once
// Zip archives, the container of FMI 2.0 FMUs, through libzip. Writing stores the entries
// uncompressed, in the order given, with a fixed 1980-01-01 00:00 time stamp and rw-r--r--
// Unix attributes, so the same entries always give the same bytes. Reading takes what
// libzip reads (stored and deflated entries, Zip64) and checks every entry's CRC-32.

#include <string>
#include <vector>

namespace chipflex
{
struct ZipEntry
{
  std::string name;  ///< path inside the archive, '/' separated, no leading '/'
  std::string bytes; ///< the uncompressed content
};

/// Writes the entries as a stored zip archive atomically (temporary file, then rename);
/// throws InputError for no entries, a name that is empty, absolute, contains ".." or
/// repeats an earlier one, or an archive libzip cannot write.
void write_zip(const std::string& path, const std::vector<ZipEntry>& entries);

/// Reads every file entry of a zip archive (folders, i.e. names ending in '/', are left
/// out); throws InputError naming the archive and entry for anything it cannot read.
std::vector<ZipEntry> read_zip(const std::string& path);

/// Unpacks a zip archive into a folder (created with its subfolders); entry names that
/// would leave the folder (absolute, "..") are refused with InputError.
void extract_zip(const std::string& path, const std::string& folder);
} // namespace chipflex
