// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/sh3d_archive.h"

#include <memory>

#include <fmt/format.h>
#include <zip.h>

namespace roomcad::sh3d {
namespace {

struct ArchiveCloser {
  void operator()(zip_t* archive) const { zip_discard(archive); }  // read-only: nothing to save
};
struct EntryCloser {
  void operator()(zip_file_t* entry) const { zip_fclose(entry); }
};

std::string describe_open_error(int code) {
  zip_error_t error;
  zip_error_init_with_code(&error, code);
  std::string text = zip_error_strerror(&error);
  zip_error_fini(&error);
  return text;
}

}  // namespace

bool is_zip_data(std::string_view bytes) { return bytes.starts_with("PK\x03\x04"); }

Result<std::string> read_home_xml_entry(const std::filesystem::path& path) {
  const std::string file = path.string();
  int code = 0;
  std::unique_ptr<zip_t, ArchiveCloser> archive(zip_open(file.c_str(), ZIP_RDONLY, &code));
  if (!archive)
    return Result<std::string>::failure(
        Code::io_error,
        fmt::format("{}: not a readable .sh3d (ZIP) archive: {}", file, describe_open_error(code)));
  const zip_int64_t index = zip_name_locate(archive.get(), "Home.xml", 0);
  if (index < 0)
    return Result<std::string>::failure(
        Code::io_error,
        fmt::format(
            "{}: the archive has no Home.xml entry (a file saved by Sweet Home 3D 5.3 or later has "
            "one)",
            file));
  zip_stat_t stat;
  zip_stat_init(&stat);
  std::unique_ptr<zip_file_t, EntryCloser> entry(zip_fopen_index(archive.get(), index, 0));
  if (zip_stat_index(archive.get(), index, 0, &stat) != 0 || !(stat.valid & ZIP_STAT_SIZE) ||
      !entry)
    return Result<std::string>::failure(
        Code::io_error, fmt::format("{}: cannot read its Home.xml entry: {}", file,
                                    zip_error_strerror(zip_get_error(archive.get()))));
  if (stat.size > kMaxHomeXmlBytes)
    return Result<std::string>::failure(
        Code::too_large,
        fmt::format("{}: its Home.xml entry is {} bytes; at most {} (256 MiB) are read", file,
                    stat.size, kMaxHomeXmlBytes));
  std::string text(stat.size, '\0');
  const zip_int64_t read = zip_fread(entry.get(), text.data(), stat.size);
  if (read < 0 || static_cast<zip_uint64_t>(read) != stat.size)
    return Result<std::string>::failure(
        Code::io_error, fmt::format("{}: its Home.xml entry is truncated or corrupt: {}", file,
                                    zip_error_strerror(zip_file_get_error(entry.get()))));
  return text;
}

}  // namespace roomcad::sh3d
