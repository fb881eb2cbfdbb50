// SPDX-License-Identifier: GPL-3.0-or-later
// Running the independent readers of tests/readers (web-ifc, the Khronos glTF validator,
// ezdxf) on files roomcad wrote. scripts/setup.sh installs them; a reader that is missing
// fails the test that needs it, naming what to run: these checks are never skipped.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace roomcad::test {

struct ReaderRun {
  int status = -1;        ///< the reader's exit status: 0 accepted, 1 rejected
  nlohmann::json report;  ///< what it printed (one JSON object)
  std::string err;        ///< what it printed on stderr
};

/// Runs tests/readers/<script> (`ifc_check.cjs`, `gltf_check.cjs`, `dxf_check.py`) on `file`.
/// @return its run, or nullopt after failing the current test (ADD_FAILURE) when the reader or
///   its interpreter is not installed, or it printed no JSON.
[[nodiscard]] std::optional<ReaderRun> run_reader(const std::string& script,
                                                  const std::filesystem::path& file);
/// The same for a reader given several files (`bcf_check.cjs` FILE.bcfzip FILE.ifc).
[[nodiscard]] std::optional<ReaderRun> run_reader(const std::string& script,
                                                  const std::vector<std::filesystem::path>& files);

}  // namespace roomcad::test
