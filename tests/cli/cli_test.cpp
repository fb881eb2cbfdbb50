// SPDX-License-Identifier: GPL-3.0-or-later
// The roomcad command: help, exit statuses, info and fmt, run as a user would.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/run_command.h"

namespace roomcad {
namespace {

namespace fs = std::filesystem;
using test::run_roomcad;

TEST(Cli, HelpOnEveryCommand) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--help"}, {"info", "--help"}, {"fmt", "--help"}, {"-h"}}) {
    const auto r = run_roomcad(args);
    EXPECT_EQ(r.status, 0) << args[0] << "\n" << r.err;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << r.out;
  }
  EXPECT_NE(run_roomcad({"--help"}).out.find("info"), std::string::npos);
  EXPECT_NE(run_roomcad({"info", "--help"}).out.find("Exit status"), std::string::npos);
  EXPECT_NE(run_roomcad({"fmt", "--help"}).out.find("--check"), std::string::npos);
  const auto version = run_roomcad({"--version"});
  EXPECT_EQ(version.status, 0);
  EXPECT_NE(version.out.find("roomcad"), std::string::npos);
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(run_roomcad({}).status, 2);
  EXPECT_EQ(run_roomcad({"frobnicate"}).status, 2);
  EXPECT_EQ(run_roomcad({"info"}).status, 2);
  EXPECT_EQ(run_roomcad({"info", "--format", "xml", "examples/house.json"}).status, 2);
  EXPECT_EQ(run_roomcad({"fmt", "--check", "-o", "x.json", "y.json"}).status, 2);
}

TEST(Cli, InfoDescribesEveryExample) {
  const auto list = test::example_plans();
  ASSERT_GE(list.size(), 4u);
  for (const fs::path& plan : list) {
    const auto r = run_roomcad({"info", plan.string()});
    EXPECT_EQ(r.status, 0) << plan << "\n" << r.err;
    EXPECT_EQ(r.err, "") << plan;
    for (const char* word : {"site", "walls", "openings", "lights", "cameras", "bounds"})
      EXPECT_NE(r.out.find(word), std::string::npos) << r.out;
  }
}

TEST(Cli, InfoOfTheHouse) {
  const fs::path house = test::source_dir() / "examples" / "house.json";
  const auto text = run_roomcad({"info", house.string()});
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("walls     21,"), std::string::npos) << text.out;

  const auto r = run_roomcad({"info", "--format", "json", house.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json info = nlohmann::json::parse(r.out);
  EXPECT_GE(info["walls"].get<int>(), 20);
  EXPECT_EQ(info["openings"].get<int>(), info["doors"].get<int>() + info["windows"].get<int>());
  EXPECT_GT(info["doors"].get<int>(), 0);
  EXPECT_GT(info["windows"].get<int>(), 0);
  EXPECT_GE(info["cameras"].get<int>(), 1);
  EXPECT_GT(info["total_wall_length"].get<double>(), 50.0);
  EXPECT_EQ(info["bounds"]["min"][2].get<double>(), 0.0);
  EXPECT_EQ(info["bounds"]["max"][2].get<double>(), 2.8);
  // Everything inside the site.
  const auto& site = info["site"];
  for (int axis : {0, 1}) {
    EXPECT_GE(info["bounds"]["min"][axis].get<double>(), site["origin"][axis].get<double>());
    EXPECT_LE(info["bounds"]["max"][axis].get<double>(),
              site["origin"][axis].get<double>() + site["size"][axis].get<double>());
  }
}

TEST(Cli, InfoOfASmallPlanIsExact) {
  test::TempDir dir;
  ASSERT_TRUE(test::write_bytes(dir / "p.json", R"({"units": "cm",
    "walls": [{"id": "a", "from": [0, 0], "to": [300, 400], "thickness": 20, "height": 250, "base": 10},
              {"id": "b", "from": [300, 400], "to": [300, 700]}],
    "openings": [{"id": "d", "wall": "a", "offset": 50}, {"id": "w", "type": "window", "wall": "a", "offset": 200}]})"));
  const auto r = run_roomcad({"info", "--format", "json", (dir / "p.json").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json info = nlohmann::json::parse(r.out);
  EXPECT_EQ(info["walls"], 2);
  EXPECT_EQ(info["doors"], 1);
  EXPECT_EQ(info["windows"], 1);
  EXPECT_EQ(info["lights"], 0);
  EXPECT_DOUBLE_EQ(info["total_wall_length"].get<double>(), 8.0);
  EXPECT_DOUBLE_EQ(info["max_wall_height"].get<double>(), 2.8);
  EXPECT_DOUBLE_EQ(info["bounds"]["min"][2].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(info["bounds"]["max"][2].get<double>(), 2.8);
  EXPECT_DOUBLE_EQ(info["bounds"]["min"][0].get<double>(), -0.08);  // 0.1 * 4/5 to the left of a
}

TEST(Cli, InfoExitStatuses) {
  test::TempDir dir;
  const auto missing = run_roomcad({"info", (dir / "nope.json").string()});
  EXPECT_EQ(missing.status, 2);
  EXPECT_EQ(test::failure_code(missing), Code::io_error);
  EXPECT_NE(missing.err.find("nope.json"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("No such file"), std::string::npos) << missing.err;

  const auto directory = run_roomcad({"info", dir.path().string()});
  EXPECT_EQ(directory.status, 2);
  EXPECT_EQ(test::failure_code(directory), Code::io_error);
  EXPECT_NE(directory.err.find("directory"), std::string::npos) << directory.err;

  ASSERT_TRUE(test::write_bytes(dir / "bad.json", "{\"walls\": [{\"id\": 1}]}"));
  const auto bad = run_roomcad({"info", (dir / "bad.json").string()});
  EXPECT_EQ(bad.status, 1);
  EXPECT_EQ(bad.out, "");
  EXPECT_NE(bad.err.find("error[parse_error]"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("bad.json:1:19: /walls/0/id: expected a string id, found 1"),
            std::string::npos)
      << bad.err;
  EXPECT_EQ(bad.err.find('\033'), std::string::npos) << "no colour when stderr is not a terminal";

  ASSERT_TRUE(test::write_bytes(dir / "empty.json", ""));
  EXPECT_EQ(run_roomcad({"info", (dir / "empty.json").string()}).status, 1);

  ASSERT_TRUE(test::write_bytes(dir / "extra.json", "{\"colour\": 1}"));
  const auto extra = run_roomcad({"info", (dir / "extra.json").string()});
  EXPECT_EQ(extra.status, 0);
  EXPECT_NE(extra.err.find("warning[unknown_field]"), std::string::npos) << extra.err;
}

TEST(Cli, FmtIsIdempotentOnEveryExample) {
  test::TempDir dir;
  for (const fs::path& plan : test::example_plans()) {
    SCOPED_TRACE(plan.string());
    const std::string original = test::read_bytes(plan);
    const fs::path copy = dir / plan.filename().string();
    ASSERT_TRUE(test::write_bytes(copy, original));
    EXPECT_EQ(run_roomcad({"fmt", "--check", copy.string()}).status, 0);
    EXPECT_EQ(run_roomcad({"fmt", copy.string()}).status, 0);
    EXPECT_EQ(test::read_bytes(copy), original);
    const auto out = run_roomcad({"fmt", copy.string(), "-o", "-"});
    EXPECT_EQ(out.status, 0);
    EXPECT_EQ(out.out, original);
  }
}

TEST(Cli, FmtRewritesInPlaceAndToAnotherFile) {
  test::TempDir dir;
  const std::string messy = R"({"units": "cm", "walls": [{"to": [400, 0], "from": [0, 0], "id": "a",
      "color": "#ABCDEF", "thickness": 25}], "note": "kept"})";
  ASSERT_TRUE(test::write_bytes(dir / "p.json", messy));

  const auto check = run_roomcad({"fmt", "--check", (dir / "p.json").string()});
  EXPECT_EQ(check.status, 1);
  EXPECT_NE(check.err.find("not in canonical form"), std::string::npos) << check.err;
  EXPECT_EQ(test::read_bytes(dir / "p.json"), messy) << "--check writes nothing";

  const auto to_other =
      run_roomcad({"fmt", (dir / "p.json").string(), "-o", (dir / "q.json").string()});
  EXPECT_EQ(to_other.status, 0) << to_other.err;
  EXPECT_EQ(test::read_bytes(dir / "p.json"), messy) << "-o leaves the input alone";
  const std::string canonical = test::read_bytes(dir / "q.json");
  EXPECT_NE(
      canonical.find(
          R"({"id": "a", "from": [0, 0], "to": [4, 0], "thickness": 0.25, "height": 2.8, "base": 0, "color": "#abcdef"})"),
      std::string::npos)
      << canonical;
  EXPECT_NE(canonical.find("  \"note\": \"kept\"\n}\n"), std::string::npos) << canonical;
  EXPECT_NE(to_other.err.find("warning[unknown_field]"), std::string::npos);

  EXPECT_EQ(run_roomcad({"fmt", (dir / "p.json").string()}).status, 0);
  EXPECT_EQ(test::read_bytes(dir / "p.json"), canonical);
  EXPECT_EQ(
      run_roomcad({"fmt", "--check", (dir / "p.json").string(), (dir / "q.json").string()}).status,
      0);
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 2u) << "no temporary file left";
}

TEST(Cli, FmtLeavesBadPlansAlone) {
  test::TempDir dir;
  const std::string bad = "{\"walls\": [{\"id\": \"a\", \"from\": [0, 0], \"to\": [1, 1e999]}]}";
  ASSERT_TRUE(test::write_bytes(dir / "bad.json", bad));
  const auto r = run_roomcad({"fmt", (dir / "bad.json").string()});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("error[invalid_value]"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("/walls/0/to/1"), std::string::npos) << r.err;
  EXPECT_EQ(test::read_bytes(dir / "bad.json"), bad);

  EXPECT_EQ(run_roomcad({"fmt", (dir / "missing.json").string()}).status, 2);
  ASSERT_TRUE(test::write_bytes(dir / "ok.json", "{}"));
  const auto unwritable =
      run_roomcad({"fmt", (dir / "ok.json").string(), "-o", (dir / "no" / "x.json").string()});
  EXPECT_EQ(unwritable.status, 2);
  EXPECT_EQ(test::failure_code(unwritable), Code::io_error);
  EXPECT_NE(unwritable.err.find("cannot write"), std::string::npos) << unwritable.err;
  // The worst status over several files.
  EXPECT_EQ(
      run_roomcad({"fmt", "--check", (dir / "bad.json").string(), (dir / "missing.json").string()})
          .status,
      2);
}

}  // namespace
}  // namespace roomcad
