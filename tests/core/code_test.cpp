// SPDX-License-Identifier: GPL-3.0-or-later
// core/code.h: every code's name, the names parsed back, which codes are findings, and the exit
// status each failure ends a command with (the plan format's "Exit status").
#include "core/code.h"

#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace roomcad {
namespace {

constexpr int kCodes = static_cast<int>(Code::internal) + 1;

Code code_at(int i) { return static_cast<Code>(i); }

TEST(Code, EveryCodeHasOneSnakeCaseNameThatParsesBack) {
  std::set<std::string_view> names;
  for (int i = 0; i < kCodes; ++i) {
    const std::string_view name = to_string(code_at(i));
    ASSERT_FALSE(name.empty()) << "code " << i;
    for (const char c : name) EXPECT_TRUE(std::islower(c) || c == '_') << name;
    EXPECT_TRUE(names.insert(name).second) << name << " names two codes";
    EXPECT_EQ(parse_code(name), code_at(i)) << name;
  }
}

TEST(Code, TheNamesAreThePlanFormatsSpelling) {
  EXPECT_EQ(to_string(Code::parse_error), "parse_error");
  EXPECT_EQ(to_string(Code::wall_overlap), "wall_overlap");
  EXPECT_EQ(to_string(Code::opening_outside_wall), "opening_outside_wall");
  EXPECT_EQ(to_string(Code::room_without_door), "room_without_door");
  EXPECT_EQ(to_string(Code::import_approximated), "import_approximated");
  EXPECT_EQ(to_string(Code::usage_error), "usage_error");
  EXPECT_EQ(to_string(Code::internal), "internal");
  std::ostringstream out;
  out << Code::slab_overlap;
  EXPECT_EQ(out.str(), "slab_overlap");
}

TEST(Code, EveryFindingIsDocumented) {
  // The plan format names the validation and rule codes; docs/cli.md the warnings about rooms.
  std::string text;
  for (const char* doc : {"/docs/plan-format.md", "/docs/cli.md", "/README.md"}) {
    std::ifstream in(std::string(ROOMCAD_SOURCE_DIR) + doc);
    ASSERT_TRUE(in) << doc;
    std::stringstream read;
    read << in.rdbuf();
    text += read.str();
  }
  for (int i = 0; i < kCodes; ++i) {
    const Code code = code_at(i);
    if (!is_finding(code) || to_string(code).starts_with("import_")) continue;
    EXPECT_NE(text.find("`" + std::string(to_string(code)) + "`"), std::string::npos)
        << to_string(code) << " is in none of docs/plan-format.md, docs/cli.md and README.md";
  }
}

TEST(Code, NamesParseExactlyOrNotAtAll) {
  for (const char* name : {"", "Wall_Overlap", "wall_overlap ", " wall_overlap", "wall-overlap",
                           "wall_overlaps", "nonsense"})
    EXPECT_EQ(parse_code(name), std::nullopt) << '"' << name << '"';
}

TEST(Code, FindingsAreThePlansAndFailuresAreTheCommands) {
  for (int i = 0; i < kCodes; ++i)
    EXPECT_EQ(is_finding(code_at(i)), i < static_cast<int>(Code::usage_error))
        << to_string(code_at(i));
}

TEST(Code, EachFailureEndsACommandWithItsExitStatus) {
  for (const Code code : {Code::usage_error, Code::io_error, Code::unsupported, Code::too_large,
                          Code::precondition, Code::lock_timeout, Code::internal})
    EXPECT_EQ(exit_status_of(code), kExitCannotRun) << to_string(code);
  for (const Code code : {Code::not_buildable, Code::edit_refused, Code::check_failed,
                          Code::wall_overlap, Code::parse_error, Code::room_unreachable})
    EXPECT_EQ(exit_status_of(code), kExitPlanErrors) << to_string(code);
  EXPECT_EQ(static_cast<int>(kExitOk), 0);
  EXPECT_EQ(static_cast<int>(kExitPlanErrors), 1);
  EXPECT_EQ(static_cast<int>(kExitCannotRun), 2);
}

}  // namespace
}  // namespace roomcad
