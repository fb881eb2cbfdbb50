#include "cli/cli_test_support.h"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

namespace roomcad::cli_test {

std::string shell_quoted(const std::filesystem::path& path) {
  return fmt::format("'{}'", path.string());
}

CommandRun run_roomcad(const std::string& args) {
  const char* env = std::getenv("ROOMCAD_EXE");
  const std::string exe = env != nullptr ? env : ROOMCAD_EXE;
  CommandRun run;
  FILE* pipe = popen(fmt::format("{} {} 2>&1", shell_quoted(exe), args).c_str(), "r");
  if (pipe == nullptr) return run;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) run.output += buffer;
  const int raw = pclose(pipe);
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return run;
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

ScratchDir::ScratchDir(const std::string& name)
    : path_(std::filesystem::temp_directory_path() / ("roomcad_test_" + name)) {
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace roomcad::cli_test
