// Reading a whole file into memory, with errors that name the file and the reason.
#pragma once

#include <filesystem>
#include <string>

#include "io/result.h"

namespace roomcad {

/// Reads the bytes of a regular file. Fails, naming the path and the reason (strerror), when it
/// does not exist, is a directory or another non-regular file, or cannot be read.
[[nodiscard]] Result<std::string> read_text_file(const std::filesystem::path& path);

}  // namespace roomcad
