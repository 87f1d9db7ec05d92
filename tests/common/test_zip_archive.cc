// common/zip_archive: the CRC-32 check value of the zip/PNG polynomial (ISO 3309:
// crc32("123456789") = 0xCBF43926), stored archives written and read back, a deflated
// archive as other tools write FMUs (here built with zlib's raw deflate and the
// PKWARE APPNOTE headers by hand), and corrupt or unsafe archives refused.

#include "common/input_error.h"
#include "common/zip_archive.h"

#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>
#include <zlib.h>

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

void put(std::string& out, std::uint32_t v, int n)
{
  for (int k = 0; k < n; ++k)
    out.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}

/// A one-entry zip whose entry is deflated (method 8), with a data descriptor-free
/// local header, as zip tools and FMU exporters write.
std::string deflated_zip(const std::string& name, const std::string& content)
{
  z_stream z{};
  REQUIRE(deflateInit2(&z, 9, Z_DEFLATED, -MAX_WBITS, 8, Z_DEFAULT_STRATEGY) == Z_OK);
  std::string packed(deflateBound(&z, content.size()), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(content.data()));
  z.avail_in = static_cast<uInt>(content.size());
  z.next_out = reinterpret_cast<Bytef*>(packed.data());
  z.avail_out = static_cast<uInt>(packed.size());
  REQUIRE(deflate(&z, Z_FINISH) == Z_STREAM_END);
  packed.resize(z.total_out);
  deflateEnd(&z);
  const std::uint32_t crc = crc32_of(content);
  std::string zip, central;
  put(zip, 0x04034b50, 4);
  for (std::uint32_t v : {20u, 0u, 8u, 0u, 0x21u})
    put(zip, v, 2);
  put(zip, crc, 4);
  put(zip, packed.size(), 4);
  put(zip, content.size(), 4);
  put(zip, name.size(), 2);
  put(zip, 0, 2);
  zip += name + packed;
  put(central, 0x02014b50, 4);
  for (std::uint32_t v : {20u, 20u, 0u, 8u, 0u, 0x21u})
    put(central, v, 2);
  put(central, crc, 4);
  put(central, packed.size(), 4);
  put(central, content.size(), 4);
  put(central, name.size(), 2);
  for (int k = 0; k < 4; ++k)
    put(central, 0, 2);
  put(central, 0, 4);
  put(central, 0, 4);
  central += name;
  const std::uint32_t offset = zip.size();
  zip += central;
  put(zip, 0x06054b50, 4);
  put(zip, 0, 2);
  put(zip, 0, 2);
  put(zip, 1, 2);
  put(zip, 1, 2);
  put(zip, central.size(), 4);
  put(zip, offset, 4);
  put(zip, 0, 2);
  return zip;
}
} // namespace

TEST_CASE("zip: CRC-32 check value, stored round trip, deflated entries, corrupt archives",
          "[common][zip]")
{
  CHECK(crc32_of("123456789") == 0xCBF43926ul);
  CHECK(crc32_of("") == 0ul);

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

  // Unpacked into a folder with its subfolders.
  const std::string folder = temp_path("unpacked");
  extract_zip(path, folder);
  CHECK(bytes_of(folder + "/binaries/linux64/x.so") == binary);

  // A deflated entry (what most zip tools write) is inflated and CRC-checked.
  std::string text;
  for (int k = 0; k < 500; ++k)
    text += "<ScalarVariable name=\"skin.position[" + std::to_string(k) + "].x\"/>\n";
  const std::string deflated = temp_path("deflated.zip");
  std::ofstream(deflated, std::ios::binary) << deflated_zip("modelDescription.xml", text);
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

  for (const auto& p : {path, again, deflated, bad})
    std::filesystem::remove(p);
  std::filesystem::remove_all(folder);
}
