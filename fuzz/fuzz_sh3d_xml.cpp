// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the Sweet Home 3D importer on arbitrary `Home.xml` text, then the plan
// writer on what it imports. Any crash, sanitizer report, uncaught exception, leak or hang is a
// bug, and so is a written plan that is not UTF-8 (no reader would take it back).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "import/sweethome3d_import.h"
#include "io/plan_json.h"
#include "io/utf8_text.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view xml(reinterpret_cast<const char*>(data), size);
  const roomcad::Result<roomcad::Sh3dImport> imported =
      roomcad::import_sweethome3d_text(xml, "fuzz.Home.xml");
  if (imported && roomcad::first_ill_formed_utf8(roomcad::write_plan_text(imported.value().plan)))
    std::abort();
  return 0;
}
