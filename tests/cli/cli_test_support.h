// Running the `roomcad` binary from tests, and reading what it wrote.
#pragma once

#include <filesystem>
#include <string>

namespace roomcad::cli_test {

struct CommandRun {
  int status = -1;
  std::string output;  ///< stdout and stderr together
};

/// Runs `roomcad ARGS` through the shell ($ROOMCAD_EXE, else the build's binary).
/// @return its exit status (-1 if it did not exit normally) and output.
CommandRun run_roomcad(const std::string& args);

/// @return the path in single quotes, for the shell.
std::string shell_quoted(const std::filesystem::path& path);

/// @return the file's bytes, empty if it cannot be read.
std::string read_bytes(const std::filesystem::path& path);

/// A fresh empty folder under the temporary directory, removed with its contents at the end.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name);
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace roomcad::cli_test
