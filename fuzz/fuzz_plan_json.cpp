// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the plan reader on arbitrary bytes, then the report printers and the writer
// on whatever it returns. Any crash, sanitizer report, uncaught exception, leak or hang is a bug;
// so is a canonical text that does not read back to itself (the writer's promise in plan_json.h).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "io/plan_json.h"
#include "validation/report_format.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  roomcad::Report report;
  const roomcad::Result<roomcad::Plan> read = roomcad::read_plan_text(text, "fuzz.json", &report);
  (void)roomcad::format_report_json(report);
  (void)roomcad::format_report_text(report, false);
  if (!read) return 0;
  const std::string canonical = roomcad::write_plan_text(read.value());
  const roomcad::Result<roomcad::Plan> again = roomcad::read_plan_text(canonical, "canonical.json");
  if (!again || roomcad::write_plan_text(again.value()) != canonical) __builtin_trap();
  return 0;
}
