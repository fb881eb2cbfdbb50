// Atomic file writes: every file roomcad writes goes through here.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

#include "core/error.h"

namespace roomcad {

/// Writes `bytes` to `path` atomically: a temporary file beside it is written, flushed to
/// disk and renamed over `path`. On any failure `path` is untouched, the temporary file is
/// removed and the returned Status names the file and the reason. A process killed midway
/// (SIGKILL, power cut) leaves `path` intact but may leave its temporary file
/// `.<name>.tmp-<pid>-XXXXXX`; the next write of `path` removes those whose process is gone.
Status write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

/// The same for content produced by a callback writing to a stream (large meshes, images).
/// The callback returns false, or throws, to abandon the write.
Status write_file_atomically(const std::filesystem::path& path,
                             const std::function<bool(std::ostream&)>& produce);

}  // namespace roomcad
