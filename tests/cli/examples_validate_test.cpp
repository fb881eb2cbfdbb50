// SPDX-License-Identifier: GPL-3.0-or-later
// Every bundled example is a valid plan: it reads, and validation finds no error.
#include <filesystem>

#include <gtest/gtest.h>

#include "io/plan_json.h"
#include "support/plan_reading.h"
#include "support/run_command.h"
#include "validation/validate.h"

namespace roomcad {
namespace {

TEST(Examples, EveryBundledExampleValidates) {
  std::size_t count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_dir() / "examples")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    ++count;
    const test::PlanReading read = test::read_plan_at(entry.path());
    ASSERT_TRUE(read.plan.has_value());
    const Report report = validate(*read.plan);
    for (const Diagnostic& d : report.items)
      EXPECT_NE(d.severity, Severity::error) << d.code << ": " << d.message;
    EXPECT_EQ(test::run_roomcad({"validate", entry.path().string()}).status, 0);
  }
  EXPECT_GE(count, 4u);
}

}  // namespace
}  // namespace roomcad
