// SPDX-License-Identifier: GPL-3.0-or-later
#include "readers_support.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include <sys/wait.h>

#include "support/run_command.h"

namespace roomcad::test {
namespace {

int shell(const std::string& command) {
  const int raw = std::system(command.c_str());
  return raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

/// The Python with Debian's python3-ezdxf: /usr/bin/python3 (a python3 earlier on the PATH,
/// such as pyenv's, does not see Debian's packages).
std::string python() {
  return std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

/// @return why the reader of `script` cannot run, or "" when it can.
std::string missing_reader(const std::string& script) {
  const std::filesystem::path readers = source_dir() / "tests" / "readers";
  if (script.ends_with(".py")) {
    if (shell(python() + " -c 'import ezdxf' >/dev/null 2>&1") != 0)
      return "ezdxf is not installed (Debian package python3-ezdxf)";
    return "";
  }
  if (shell("command -v node >/dev/null 2>&1") != 0)
    return "node is not installed (Debian package nodejs)";
  const char* package = script == "ifc_check.cjs"   ? "web-ifc"
                        : script == "bcf_check.cjs" ? "@parametricos/bcf-js"
                                                    : "gltf-validator";
  if (!std::filesystem::exists(readers / "node_modules" / package / "package.json"))
    return std::string(package) + " is not installed in tests/readers/node_modules";
  return "";
}

}  // namespace

std::optional<ReaderRun> run_reader(const std::string& script, const std::filesystem::path& file) {
  return run_reader(script, std::vector<std::filesystem::path>{file});
}

std::optional<ReaderRun> run_reader(const std::string& script,
                                    const std::vector<std::filesystem::path>& files) {
  if (const std::string missing = missing_reader(script); !missing.empty()) {
    ADD_FAILURE() << "the independent reader " << script << " cannot run: " << missing
                  << ". Run scripts/setup.sh, which installs it.";
    return std::nullopt;
  }
  TempDir dir;
  const std::string interpreter = script.ends_with(".py") ? python() : "node";
  std::string command = interpreter + " '" + (source_dir() / "tests" / "readers" / script).string();
  for (const std::filesystem::path& file : files) command += "' '" + file.string();
  command += "' >'" + (dir / "out").string() + "' 2>'" + (dir / "err").string() + "'";
  ReaderRun run;
  run.status = shell(command);
  run.err = read_bytes(dir / "err");
  const std::string out = read_bytes(dir / "out");
  run.report = nlohmann::json::parse(out, nullptr, false);
  if (run.report.is_discarded() || !run.report.is_object()) {
    ADD_FAILURE() << command << " printed no JSON report (exit " << run.status << "):\n"
                  << out << run.err;
    return std::nullopt;
  }
  return run;
}

}  // namespace roomcad::test
