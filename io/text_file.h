// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a whole file into memory, with errors that name the file and the reason.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/error.h"

namespace roomcad {

/// Largest file read_text_file reads. Plans and Sweet Home 3D homes are parsed into documents
/// several times their size, so a bigger file would only exhaust memory (the eteks example
/// homes are under 200 KB, a plan of 10,000 walls about 1.5 MB).
inline constexpr std::uintmax_t kMaxTextFileBytes = 256u << 20;

/// Reads the bytes of a regular file. Fails, naming the path and the reason (strerror), when it
/// does not exist, is a directory or another non-regular file, is larger than
/// kMaxTextFileBytes (unread), or cannot be read.
[[nodiscard]] Result<std::string> read_text_file(const std::filesystem::path& path);

}  // namespace roomcad
