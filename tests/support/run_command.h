// SPDX-License-Identifier: GPL-3.0-or-later
// Running the roomcad binary from tests and capturing what it prints.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/code.h"

namespace roomcad::test {

struct CommandResult {
  int status = -1;  ///< exit status, or -1 if the command did not exit normally
  std::string out;  ///< what it printed on stdout
  std::string err;  ///< what it printed on stderr
};

/// @return the roomcad binary under test: $ROOMCAD_EXE, else the ROOMCAD_EXE define.
[[nodiscard]] std::string roomcad_exe();

/// Runs `roomcad args...` (each argument shell-quoted), with stdin from /dev/null.
[[nodiscard]] CommandResult run_roomcad(const std::vector<std::string>& args);

/// Runs a program (found on PATH) with its arguments, as run_roomcad does.
[[nodiscard]] CommandResult run_program(const std::string& program,
                                        const std::vector<std::string>& args);

/// @return the code of the failure the command reported ("roomcad CMD: error[CODE]: ..." on
///         stderr, cli/command.h), or nullopt when it reported none or a name no Code has.
[[nodiscard]] std::optional<Code> failure_code(const CommandResult& result);

/// A fresh empty directory under the system temporary directory, removed with its contents
/// when the object is destroyed.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  [[nodiscard]] std::filesystem::path operator/(const std::string& name) const {
    return path_ / name;
  }

 private:
  std::filesystem::path path_;
};

/// Writes `bytes` to `path` (plain write, for setting up tests). @return false on failure.
bool write_bytes(const std::filesystem::path& path, const std::string& bytes);
/// Makes `path` a sparse file of `size` bytes (no disk space used), for size limits.
/// @return false on failure.
bool make_sparse_file(const std::filesystem::path& path, std::uintmax_t size);
/// @return the bytes of `path`, or "" if it cannot be read.
[[nodiscard]] std::string read_bytes(const std::filesystem::path& path);

/// @return the project's source directory (the ROOMCAD_SOURCE_DIR define or the environment).
[[nodiscard]] std::filesystem::path source_dir();

/// @return the bundled example plans, examples/*.json of source_dir(), sorted by path.
[[nodiscard]] std::vector<std::filesystem::path> example_plans();

}  // namespace roomcad::test
