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
  const roomcad::PlanReadResult read = roomcad::read_plan_text(text, "fuzz.json");
  (void)roomcad::format_report_json(read.report);
  (void)roomcad::format_report_text(read.report, false);
  if (!read.plan) return 0;
  const std::string canonical = roomcad::write_plan_text(*read.plan);
  const roomcad::PlanReadResult again = roomcad::read_plan_text(canonical, "canonical.json");
  if (!again.plan || roomcad::write_plan_text(*again.plan) != canonical) __builtin_trap();
  return 0;
}
