// common/zip_archive: stored archives written and read back, byte-identical for the same
// entries (the fixed 1980-01-01 time stamp in every header), a deflated archive as other
// tools write FMUs, and corrupt or unsafe archives refused.

#include "common/input_error.h"
#include "common/zip_archive.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>
#include <zip.h>

using namespace chipflex;

namespace
{
std::string temp_path(const std::string& name)
{
  return (std::filesystem::temp_directory_path() /
          ("chipflex_zip_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

std::string bytes_of(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// A one-entry zip whose entry is deflated (method 8), as most zip tools and FMU
/// exporters write, here by libzip itself.
void write_deflated_zip(const std::string& path, const std::string& name,
                        const std::string& content)
{
  int code = 0;
  zip_t* z = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &code);
  REQUIRE(z);
  zip_source_t* source = zip_source_buffer(z, content.data(), content.size(), 0);
  REQUIRE(source);
  const zip_int64_t index = zip_file_add(z, name.c_str(), source, 0);
  REQUIRE(index == 0);
  REQUIRE(zip_set_file_compression(z, 0, ZIP_CM_DEFLATE, 9) == 0);
  REQUIRE(zip_close(z) == 0);
}
} // namespace

TEST_CASE("zip: stored round trip, same bytes, deflated entries, corrupt archives", "[common][zip]")
{
  const std::string path = temp_path("stored.zip");
  std::string binary(3000, '\0');
  for (std::size_t k = 0; k < binary.size(); ++k)
    binary[k] = static_cast<char>((k * 7919) % 256);
  write_zip(path, {{"modelDescription.xml", "<fmiModelDescription/>"},
                   {"binaries/linux64/x.so", binary},
                   {"resources/empty", ""}});
  const auto entries = read_zip(path);
  REQUIRE(entries.size() == 3);
  CHECK(entries[0].name == "modelDescription.xml");
  CHECK(entries[1].bytes == binary);
  CHECK(entries[2].bytes.empty());
  // Same entries, same bytes (fixed time stamps).
  const std::string again = temp_path("again.zip");
  write_zip(again, {{"modelDescription.xml", "<fmiModelDescription/>"},
                    {"binaries/linux64/x.so", binary},
                    {"resources/empty", ""}});
  CHECK(bytes_of(path) == bytes_of(again));
  // The first local header: stored (method 0 at byte 8), time 00:00 and date 1980-01-01
  // (MS-DOS fields at bytes 10-13), whatever the clock and time zone.
  const std::string header = bytes_of(path).substr(0, 14);
  CHECK(header.substr(0, 4) == std::string("PK\x03\x04"));
  CHECK(header.substr(8) == std::string("\0\0\0\0\x21\0", 6));

  // Unpacked into a folder with its subfolders.
  const std::string folder = temp_path("unpacked");
  extract_zip(path, folder);
  CHECK(bytes_of(folder + "/binaries/linux64/x.so") == binary);

  // A deflated entry (what most zip tools write) is inflated and CRC-checked.
  std::string text;
  for (int k = 0; k < 500; ++k)
    text += "<ScalarVariable name=\"skin.position[" + std::to_string(k) + "].x\"/>\n";
  const std::string deflated = temp_path("deflated.zip");
  write_deflated_zip(deflated, "modelDescription.xml", text);
  const auto inflated = read_zip(deflated);
  REQUIRE(inflated.size() == 1);
  CHECK(inflated[0].bytes == text);
  CHECK(std::filesystem::file_size(deflated) < text.size() / 4);

  // A flipped byte in the stored data: CRC mismatch, named.
  std::string corrupt = bytes_of(path);
  corrupt[30 + std::string("modelDescription.xml").size() + 3] ^= 0x40;
  const std::string bad = temp_path("corrupt.zip");
  std::ofstream(bad, std::ios::binary) << corrupt;
  CHECK_THROWS_WITH(read_zip(bad), Catch::Contains("CRC-32"));
  std::ofstream(bad, std::ios::binary) << "not a zip archive at all";
  CHECK_THROWS_AS(read_zip(bad), InputError);
  CHECK_THROWS_AS(write_zip(bad, {{"../escape", "x"}}), InputError);
  CHECK_THROWS_AS(write_zip(bad, {{"/absolute", "x"}}), InputError);
  CHECK_THROWS_WITH(write_zip(bad, {{"a", "x"}, {"a", "y"}}), Catch::Contains("cannot add 'a'"));
  CHECK_THROWS_AS(write_zip(bad, {}), InputError);

  for (const auto& p : {path, again, deflated, bad})
    std::filesystem::remove(p);
  std::filesystem::remove_all(folder);
}
