// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/text_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include <sys/stat.h>

namespace roomcad {

Result<std::string> read_text_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  auto failure = [&](const std::string& why, Code code = Code::io_error) {
    return Result<std::string>::failure(code, "cannot read " + name + ": " + why);
  };
  struct stat info {};
  if (::stat(name.c_str(), &info) != 0) return failure(std::strerror(errno));
  if (S_ISDIR(info.st_mode)) return failure("it is a directory, not a file");
  if (!S_ISREG(info.st_mode)) return failure("it is not a regular file");
  if (static_cast<std::uintmax_t>(info.st_size) > kMaxTextFileBytes)
    return failure("it is " + std::to_string(info.st_size) + " bytes; files of at most " +
                       std::to_string(kMaxTextFileBytes) + " bytes (256 MiB) are read",
                   Code::too_large);

  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(name.c_str(), "rb"), std::fclose);
  if (!file) return failure(std::strerror(errno));
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(info.st_size));
  char buffer[1 << 16];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) bytes.append(buffer, n);
  if (std::ferror(file.get())) return failure(std::strerror(errno));
  return bytes;
}

}  // namespace roomcad
