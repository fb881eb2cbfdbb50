// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the `.sh3d` (ZIP) path of the Sweet Home 3D importer. libzip reads archives
// from files, and import_sweethome3d_file is the entry point users reach, so each input is
// written to a scratch file first. Any crash, sanitizer report, leak or hang is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "import/sweethome3d_import.h"

namespace {

/// One scratch file per fuzzing process (parallel jobs must not share it).
const std::filesystem::path& scratch_path() {
  static const std::filesystem::path path =
      std::filesystem::temp_directory_path() /
      ("roomcad-fuzz-" + std::to_string(::getpid()) + ".sh3d");
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::FILE* file = std::fopen(scratch_path().c_str(), "wb");
  if (!file) __builtin_trap();  // the harness itself is broken: say so loudly
  std::fwrite(data, 1, size, file);
  std::fclose(file);
  (void)roomcad::import_sweethome3d_file(scratch_path());
  return 0;
}
