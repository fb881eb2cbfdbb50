// SPDX-License-Identifier: GPL-3.0-or-later
#include "support/run_command.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include <sys/wait.h>
#include <unistd.h>

namespace roomcad::test {
namespace {

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string roomcad_exe() {
  if (const char* exe = std::getenv("ROOMCAD_EXE"); exe != nullptr && *exe != '\0') return exe;
#ifdef ROOMCAD_EXE
  return ROOMCAD_EXE;
#else
  return "roomcad";
#endif
}

std::filesystem::path source_dir() {
  if (const char* dir = std::getenv("ROOMCAD_SOURCE_DIR"); dir != nullptr && *dir != '\0')
    return dir;
#ifdef ROOMCAD_SOURCE_DIR
  return ROOMCAD_SOURCE_DIR;
#else
  return std::filesystem::current_path();
#endif
}

std::vector<std::filesystem::path> example_plans() {
  std::vector<std::filesystem::path> plans;
  for (const auto& e : std::filesystem::directory_iterator(source_dir() / "examples"))
    if (e.path().extension() == ".json") plans.push_back(e.path());
  std::sort(plans.begin(), plans.end());
  return plans;
}

CommandResult run_roomcad(const std::vector<std::string>& args) {
  return run_program(roomcad_exe(), args);
}

CommandResult run_program(const std::string& program, const std::vector<std::string>& args) {
  TempDir dir;
  const auto out_path = dir / "stdout";
  const auto err_path = dir / "stderr";
  std::string command = shell_quote(program);
  for (const std::string& a : args) command += ' ' + shell_quote(a);
  command +=
      " </dev/null >" + shell_quote(out_path.string()) + " 2>" + shell_quote(err_path.string());
  const int raw = std::system(command.c_str());
  CommandResult result;
  result.status = raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  result.out = read_bytes(out_path);
  result.err = read_bytes(err_path);
  return result;
}

TempDir::TempDir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "roomcad-test-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  path_ = pattern;
}

TempDir::~TempDir() {
  std::error_code ignored;
  // Tests may leave read-only folders behind; make them writable so they can be removed.
  for (auto it = std::filesystem::recursive_directory_iterator(path_, ignored);
       it != std::filesystem::recursive_directory_iterator(); it.increment(ignored)) {
    if (it->is_directory(ignored))
      std::filesystem::permissions(it->path(), std::filesystem::perms::owner_all,
                                   std::filesystem::perm_options::add, ignored);
  }
  std::filesystem::permissions(path_, std::filesystem::perms::owner_all,
                               std::filesystem::perm_options::add, ignored);
  std::filesystem::remove_all(path_, ignored);
}

bool write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return static_cast<bool>(out.flush());
}

std::optional<Code> failure_code(const CommandResult& result) {
  // The first line of the form "roomcad ...: error[CODE]: ...".
  for (std::size_t line = 0; line < result.err.size();) {
    const std::size_t end = std::min(result.err.find('\n', line), result.err.size());
    const std::string_view text(result.err.data() + line, end - line);
    const std::size_t open = text.find(": error[");
    if (text.starts_with("roomcad") && open != std::string_view::npos) {
      const std::size_t from = open + 8, close = text.find(']', from);
      if (close != std::string_view::npos) return parse_code(text.substr(from, close - from));
    }
    line = end + 1;
  }
  return std::nullopt;
}

bool make_sparse_file(const std::filesystem::path& path, std::uintmax_t size) {
  if (!write_bytes(path, "")) return false;
  std::error_code error;
  std::filesystem::resize_file(path, size, error);  // truncate(2): a hole, no blocks
  return !error;
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace roomcad::test
