// SPDX-License-Identifier: GPL-3.0-or-later
// Atomic file writes: every file roomcad writes goes through here.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

#include "core/error.h"

namespace roomcad {

/// Writes `bytes` to `path` atomically and durably: a temporary file beside it is written,
/// flushed to disk (fsync), renamed over `path`, and then the folder is flushed to disk
/// (fsync), so that once this returns success a power cut leaves the new file, and before
/// that the old one (or none, for a new file), never an empty or partial file. On a failure
/// before the rename `path` is untouched, the temporary file is removed and the returned Status
/// (io_error) names the file and the reason; a failure to flush the folder after the rename is
/// reported too, saying the new file is in place but not yet safe from a power cut. A process
/// killed midway (SIGKILL, power cut) leaves `path` intact but may leave its temporary file
/// `.<name>.tmp-<pid>-XXXXXX`; the next write of `path` removes those whose process is gone.
/// Cost: the writes, plus the two fsyncs, which dominate small files (bench/report.md, "Edits").
Status write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

/// The same for content produced by a callback writing to a stream (large meshes, images).
/// The callback returns false, or throws, to abandon the write.
Status write_file_atomically(const std::filesystem::path& path,
                             const std::function<bool(std::ostream&)>& produce);

}  // namespace roomcad
