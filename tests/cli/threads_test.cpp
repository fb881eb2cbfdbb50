// SPDX-License-Identifier: GPL-3.0-or-later
// Outputs do not depend on the thread count: `roomcad build` and `roomcad render` on every
// bundled example write the same bytes with --threads 1 and --threads 2; out of range exits 2.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "support/run_command.h"

namespace roomcad {
namespace {

namespace fs = std::filesystem;
using test::run_roomcad;

TEST(Threads, BuildWritesTheSameBytesAtOneAndTwoThreads) {
  const std::vector<fs::path> plans = test::example_plans();
  ASSERT_GE(plans.size(), 4u);
  test::TempDir dir;
  // The same file name in two folders: an OBJ names its MTL file.
  fs::create_directory(dir / "1");
  fs::create_directory(dir / "2");
  for (const fs::path& plan : plans) {
    const std::string obj = plan.stem().string() + ".obj";
    const std::string mtl = plan.stem().string() + ".mtl";
    for (const char* threads : {"1", "2"}) {
      const auto out = dir / threads / obj;
      const auto r =
          run_roomcad({"build", plan.string(), "--threads", threads, "-o", out.string()});
      ASSERT_EQ(r.status, 0) << obj << " --threads " << threads << ": " << r.err;
    }
    const std::string one = test::read_bytes(dir / "1" / obj);
    EXPECT_GT(one.size(), 1000u) << obj;
    EXPECT_TRUE(one == test::read_bytes(dir / "2" / obj)) << obj << " differs";
    EXPECT_EQ(test::read_bytes(dir / "1" / mtl), test::read_bytes(dir / "2" / mtl)) << mtl;
  }
}

TEST(Threads, RenderWritesTheSameBytesAtOneAndTwoThreads) {
  test::TempDir dir;
  for (const fs::path& plan : test::example_plans()) {
    const std::string name = plan.stem().string();
    for (const char* threads : {"1", "2"}) {
      const auto out = dir / (name + "-" + threads + ".png");
      const auto r = run_roomcad({"render", plan.string(), "--width", "200", "--height", "150",
                                  "--ssaa", "2", "--threads", threads, "-o", out.string()});
      ASSERT_EQ(r.status, 0) << name << " --threads " << threads << ": " << r.err;
    }
    const std::string one = test::read_bytes(dir / (name + "-1.png"));
    EXPECT_GT(one.size(), 1000u) << name;
    EXPECT_TRUE(one == test::read_bytes(dir / (name + "-2.png"))) << name << " differs";
  }
}

TEST(Threads, RenderRefusesFramesThreadsAndShadowMapsPastTheLimits) {
  test::TempDir dir;
  const std::string plan = (test::source_dir() / "examples/studio.json").string();
  const std::string out = (dir / "p.png").string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--threads", "257"}, "--threads: Value 257 not in range 0 to 256"},
      {{"--width", "16385"}, "--width: Value 16385 not in range 1 to 16384"},
      {{"--width", "16384", "--height", "16384"},
       "--width 16384 x --height 16384 is 268435456 pixels; at most 67108864"},
      {{"--width", "8192", "--height", "8192", "--ssaa", "4"},
       "--width 8192 x --height 8192 at --ssaa 4 is 1073741824 samples; at most 268435456"},
      {{"--shadow-res", "8193"}, "--shadow-res: Value 8193 not in range 1 to 8192"}};
  for (const auto& [flags, message] : cases) {
    std::vector<std::string> args = {"render", plan, "-o", out};
    args.insert(args.end(), flags.begin(), flags.end());
    const auto r = run_roomcad(args);
    EXPECT_EQ(r.status, 2) << flags[0];
    EXPECT_EQ(test::failure_code(r), Code::usage_error) << flags[0];
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST(Threads, BuildRefusesAThreadCountOutOfRange) {
  test::TempDir dir;
  const std::string plan = (test::source_dir() / "examples/studio.json").string();
  for (const char* threads : {"-1", "257", "100000"}) {
    const auto r =
        run_roomcad({"build", plan, "--threads", threads, "-o", (dir / "m.obj").string()});
    EXPECT_EQ(r.status, 2) << threads;
    EXPECT_EQ(test::failure_code(r), Code::usage_error) << threads;
    EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "m.obj"));
  }
}

}  // namespace
}  // namespace roomcad
