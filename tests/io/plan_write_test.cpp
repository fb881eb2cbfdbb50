// SPDX-License-Identifier: GPL-3.0-or-later
// Writing plans: the canonical layout, shortest numbers, round trips.
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "io/plan_json.h"
#include "plan_test_support.h"
#include "support/plan_reading.h"
#include "support/run_command.h"
#include "testing/random_plan.h"

namespace roomcad {
namespace {

using test::read_ok;

TEST(PlanWrite, SpecExampleInCanonicalForm) {
  EXPECT_EQ(write_plan_text(read_ok(test::kSpecExample)), test::kSpecCanonical);
}

TEST(PlanWrite, CanonicalTextIsReproducedByteForByte) {
  const std::string canonical(test::kSpecCanonical);
  EXPECT_EQ(write_plan_text(read_ok(canonical)), canonical);
}

TEST(PlanWrite, EmptyPlan) {
  EXPECT_EQ(
      write_plan_text(Plan{}),
      "{\n"
      "  \"format\": \"roomcad-plan\",\n"
      "  \"version\": 1,\n"
      "  \"units\": \"m\",\n"
      "  \"site\": {\"origin\": [0, 0], \"cells\": [12, 8], \"cell_size\": 1, \"max_height\": 6, "
      "\"tolerance\": 1e-06, \"floor_color\": \"#c8c8c8\"},\n"
      "  \"walls\": [],\n"
      "  \"openings\": [],\n"
      "  \"lights\": [],\n"
      "  \"cameras\": []\n"
      "}\n");
}

std::string written_x(double x) {
  Plan p;
  p.site.origin.x = x;
  const std::string text = write_plan_text(p);
  const auto start = text.find("\"origin\": [") + 11;
  return text.substr(start, text.find(',', start) - start);
}

TEST(PlanWrite, NumbersAreTheShortestThatReadBack) {
  EXPECT_EQ(written_x(0.0), "0");
  EXPECT_EQ(written_x(-0.0), "-0");
  EXPECT_EQ(written_x(3.0), "3");
  EXPECT_EQ(written_x(-250.0), "-250");
  EXPECT_EQ(written_x(0.1), "0.1");
  EXPECT_EQ(written_x(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(written_x(2.8), "2.8");
  EXPECT_EQ(written_x(1e-6), "1e-06");
  EXPECT_EQ(written_x(123456789012345.0), "123456789012345");
  EXPECT_EQ(written_x(1e15), "1e+15");
  EXPECT_EQ(written_x(1e21), "1e+21");
  EXPECT_EQ(written_x(5e-324), "5e-324");
  EXPECT_EQ(written_x(std::numeric_limits<double>::max()), "1.7976931348623157e+308");
  EXPECT_EQ(written_x(0.8660254037844386), "0.8660254037844386");
  EXPECT_EQ(written_x(std::numeric_limits<double>::infinity()), "null");  // JSON has no infinity
}

TEST(PlanWrite, MinusZeroRoundTrips) {
  Plan p;
  Wall w;
  w.id = "a";
  w.from = {-0.0, 0.0};
  w.to = {1, -0.0};
  w.base = -0.0;
  p.walls.push_back(w);
  const std::string text = write_plan_text(p);
  EXPECT_NE(text.find("\"from\": [-0, 0], \"to\": [1, -0]"), std::string::npos) << text;
  const Plan back = read_ok(text);
  EXPECT_TRUE(std::signbit(back.walls[0].from.x));
  EXPECT_FALSE(std::signbit(back.walls[0].from.y));
  EXPECT_TRUE(std::signbit(back.walls[0].to.y));
  EXPECT_TRUE(std::signbit(back.walls[0].base));
  EXPECT_EQ(write_plan_text(back), text);
}

TEST(PlanWrite, StringsAreEscaped) {
  Plan p;
  Wall w;
  w.id = "q\"b\\s/\n\t\x01\x7f é日本";
  w.to = {1, 0};
  p.walls.push_back(w);
  const std::string text = write_plan_text(p);
  EXPECT_NE(text.find(R"({"id": "q\"b\\s/\n\t\u0001\u007f é日本", )"), std::string::npos) << text;
  EXPECT_EQ(read_ok(text), p);
}

TEST(PlanWrite, ExtrasAfterKnownKeysSortedAndKnownKeysNeverRepeated) {
  Plan p;
  p.site.extra = {{"zz", "1"}, {"aa", "[true, null]"}, {"cells", "3"}, {"aa", "2"}};
  p.extra = {{"b", "{}"}, {"a", "\"x\""}, {"walls", "[]"}};
  const std::string text = write_plan_text(p);
  EXPECT_NE(text.find("\"floor_color\": \"#c8c8c8\", \"aa\": [true, null], \"zz\": 1}"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("  \"cameras\": [],\n  \"a\": \"x\",\n  \"b\": {}\n}\n"), std::string::npos)
      << text;
  EXPECT_EQ(text.find("\"walls\": [],\n  \"openings\": [],\n  \"lights\": [],\n  \"cameras\": "
                      "[],\n  \"walls\""),
            std::string::npos);
  const test::PlanReading r = test::read_plan(text, "x.json");
  EXPECT_TRUE(r.report.ok()) << r.report.items[0].message;
}

TEST(PlanWrite, UnknownFieldValuesAreKeptCanonically) {
  const char* text = R"({"x": {"b": [1, 2.50, -0.0, 1e2, "s"], "a": {"d": false, "c": null}}})";
  const Plan p = read_ok(text);
  ASSERT_EQ(p.extra.size(), 1u);
  EXPECT_EQ(p.extra[0].json, R"({"a": {"c": null, "d": false}, "b": [1, 2.5, -0, 100, "s"]})");
  const std::string saved = write_plan_text(p);
  EXPECT_EQ(write_plan_text(read_ok(saved)), saved);
}

TEST(PlanWrite, RandomPlansRoundTrip) {
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Plan plan = samples::random_plan(seed);
    const std::string text = write_plan_text(plan);
    const test::PlanReading r = test::read_plan(text, "random.json");
    ASSERT_TRUE(r.plan.has_value()) << r.report.items[0].message << "\n" << text;
    EXPECT_EQ(r.report.warning_count(), r.report.items.size());
    EXPECT_EQ(*r.plan, plan) << text;
    EXPECT_EQ(write_plan_text(*r.plan), text);
  }
}

TEST(PlanWrite, RandomPlansDifferBySeed) {
  EXPECT_EQ(samples::random_plan(7), samples::random_plan(7));
  EXPECT_NE(samples::random_plan(7), samples::random_plan(8));
}

TEST(PlanWrite, ExamplesRoundTrip) {
  const auto dir = test::source_dir() / "examples";
  std::size_t count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    ++count;
    const test::PlanReading r = test::read_plan_at(entry.path());
    ASSERT_TRUE(r.plan.has_value()) << r.report.items[0].message;
    EXPECT_TRUE(r.report.items.empty()) << r.report.items[0].message;
    const std::string text = write_plan_text(*r.plan);
    EXPECT_EQ(text, test::read_bytes(entry.path())) << "examples are kept in canonical form";
    const Plan back = read_ok(text);
    EXPECT_EQ(back, *r.plan);
    EXPECT_EQ(write_plan_text(back), text);
  }
  EXPECT_GE(count, 4u);
}

TEST(PlanWrite, FileIsWrittenAndReadBack) {
  test::TempDir dir;
  const Plan plan = samples::random_plan(42);
  ASSERT_TRUE(write_plan_file(plan, dir / "p.json").ok());
  const test::PlanReading r = test::read_plan_at(dir / "p.json");
  ASSERT_TRUE(r.plan.has_value());
  EXPECT_EQ(*r.plan, plan);
}

/// @return a plan of one wall 1 m long named `id`.
Plan one_wall(std::string id) {
  Plan plan;
  Wall& w = plan.walls.emplace_back();
  w.id = std::move(id);
  w.to = {1, 0};
  return plan;
}

TEST(PlanWrite, NonFiniteNumbersAreRefusedAndNothingIsWritten) {
  test::TempDir dir;
  ASSERT_TRUE(test::write_bytes(dir / "p.json", "old"));
  Plan plan = one_wall("w1");
  plan.walls[0].thickness = std::nan("");
  const Status s = write_plan_file(plan, dir / "p.json");
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("wall 'w1' field 'thickness'"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("p.json"), std::string::npos) << s.message();
  EXPECT_EQ(test::read_bytes(dir / "p.json"), "old");
}

TEST(PlanWrite, TextThatIsNotUtf8IsRefusedAndNothingIsWritten) {
  // A plan is UTF-8: written, an ill-formed byte would make the file unreadable.
  test::TempDir dir;
  ASSERT_TRUE(test::write_bytes(dir / "p.json", "old"));
  Plan plan = one_wall("w\xff");
  Status s = write_plan_file(plan, dir / "p.json");
  EXPECT_EQ(s.code(), Code::invalid_value);
  EXPECT_EQ(s.message(), "cannot write " + (dir / "p.json").string() +
                             ": wall 'w\\xFF' field 'id' holds text that is not UTF-8 (JSON "
                             "cannot hold it)");
  plan.walls[0].id = "w1";
  plan.walls[0].extra.push_back({"note\xc3", "1"});
  s = write_plan_file(plan, dir / "p.json");
  EXPECT_EQ(s.message(), "cannot write " + (dir / "p.json").string() +
                             ": wall 'w1' has an unknown field named 'note\\xC3', which is not "
                             "UTF-8 (JSON cannot hold it)");
  EXPECT_EQ(test::read_bytes(dir / "p.json"), "old");
}

TEST(PlanWrite, FailedWriteLeavesTheOldFile) {
  test::TempDir dir;
  const Status s = write_plan_file(Plan{}, dir / "missing" / "p.json");
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("missing/p.json"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("No such file or directory"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace roomcad
