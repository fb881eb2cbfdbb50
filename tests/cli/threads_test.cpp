// Outputs do not depend on the thread count: `roomcad build` on every bundled example writes
// the same bytes with --threads 1 and --threads 2; --threads out of range exits 2.
#include <filesystem>
#include <string>
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
      const auto r = run_roomcad({"build", plan.string(), "--threads", threads, "-o", out.string()});
      ASSERT_EQ(r.status, 0) << obj << " --threads " << threads << ": " << r.err;
    }
    const std::string one = test::read_bytes(dir / "1" / obj);
    EXPECT_GT(one.size(), 1000u) << obj;
    EXPECT_TRUE(one == test::read_bytes(dir / "2" / obj)) << obj << " differs";
    EXPECT_EQ(test::read_bytes(dir / "1" / mtl), test::read_bytes(dir / "2" / mtl)) << mtl;
  }
}

TEST(Threads, BuildRefusesAThreadCountOutOfRange) {
  test::TempDir dir;
  const std::string plan = (test::source_dir() / "examples/studio.json").string();
  for (const char* threads : {"-1", "257", "100000"}) {
    const auto r =
        run_roomcad({"build", plan, "--threads", threads, "-o", (dir / "m.obj").string()});
    EXPECT_EQ(r.status, 2) << threads;
    EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "m.obj"));
  }
}

}  // namespace
}  // namespace roomcad
