// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad import` run as a program: exit statuses, the plan file it writes, its messages, the
// lock of the plan it replaces.
#include <chrono>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "import/sweethome3d_import.h"
#include "io/plan_json.h"
#include "io/plan_lock.h"
#include "support/plan_reading.h"
#include "support/run_command.h"

namespace roomcad {
namespace {

namespace fs = std::filesystem;
using test::run_roomcad;

const fs::path kHomes = test::source_dir() / "examples" / "sweethome3d" / "homes";

TEST(ImportCommand, WritesThePlanTheImporterBuilds) {
  const test::TempDir dir;
  const fs::path home = kHomes / "eteks-example-homes" / "1-BedroomApartment.Home.xml";
  const test::CommandResult run = run_roomcad({"import", home.string(), "-o", dir / "a.json"});
  ASSERT_EQ(run.status, 0) << run.err;
  // The curved wall comes in as an arc: nothing to warn about; the summary counts the plan.
  EXPECT_EQ(run.err.find("import_curved_wall"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("0 levels, 14 walls, 12 openings and 0 slabs"), std::string::npos)
      << run.err;
  const test::PlanReading read = test::read_plan_at(dir / "a.json");
  ASSERT_TRUE(read.plan.has_value());
  EXPECT_TRUE(read.report.ok());
  const Result<Sh3dImport> imported = import_sweethome3d_file(home);
  ASSERT_TRUE(imported.ok());
  EXPECT_EQ(*read.plan, imported.value().plan);
}

TEST(ImportCommand, OneLevelByName) {
  const test::TempDir dir;
  const fs::path home = kHomes / "eteks-example-homes" / "2-BedroomHouseWithBasement.Home.xml";
  const test::CommandResult run =
      run_roomcad({"import", home.string(), "-o", dir / "b.json", "--level", "Basement"});
  ASSERT_EQ(run.status, 0) << run.err;
  const test::PlanReading read = test::read_plan_at(dir / "b.json");
  ASSERT_TRUE(read.plan.has_value());
  EXPECT_EQ(read.plan->walls.size(), 14u);  // the <wall level='level0'> elements of the file
  for (const Wall& w : read.plan->walls) EXPECT_EQ(w.base, 0.0);
}

TEST(ImportCommand, BadInputExitsTwoNamingTheFileAndWritesNothing) {
  const test::TempDir dir;
  ASSERT_TRUE(test::write_bytes(dir / "broken.xml", "<home><wall id='w'"));
  const std::string plan = dir / "out.json";
  test::CommandResult run = run_roomcad({"import", dir / "broken.xml", "-o", plan});
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(test::failure_code(run), Code::parse_error);
  EXPECT_NE(run.err.find("broken.xml: malformed XML"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(plan));

  run = run_roomcad({"import", dir / "absent.sh3d", "-o", plan});
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(test::failure_code(run), Code::io_error);
  EXPECT_NE(run.err.find("absent.sh3d"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(plan));

  const fs::path sample = kHomes / "edge-cases" / "Sample.Home.xml";
  run = run_roomcad({"import", sample.string(), "-o", plan, "--level", "Attic"});
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(test::failure_code(run), Code::usage_error);
  EXPECT_NE(run.err.find("--level 'Attic' names no level"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(plan));
}

TEST(ImportCommand, UnwritableOutputExitsTwo) {
  const test::TempDir dir;
  const fs::path home = kHomes / "eteks-example-homes" / "Studio.Home.xml";
  const test::CommandResult run =
      run_roomcad({"import", home.string(), "-o", dir / "no-such-dir" / "p.json"});
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(test::failure_code(run), Code::io_error);
  EXPECT_NE(run.err.find("no-such-dir"), std::string::npos) << run.err;
}

TEST(ImportCommand, ReplacesAPlanOnlyUnderItsLock) {
  const test::TempDir dir;
  const fs::path home = kHomes / "eteks-example-homes" / "Studio.Home.xml";
  const fs::path plan = dir / "p.json";
  ASSERT_TRUE(test::write_bytes(plan, "{}"));  // another editor's plan, being edited
  {
    const Result<PlanLock> held =
        PlanLock::acquire(plan, std::chrono::milliseconds(0), "roomcad set");
    ASSERT_TRUE(held.ok()) << held.error();
    const test::CommandResult run =
        run_roomcad({"import", home.string(), "-o", plan.string(), "--wait", "0.1"});
    EXPECT_EQ(run.status, 2);
    EXPECT_EQ(test::failure_code(run), Code::lock_timeout) << run.err;
    EXPECT_NE(run.err.find("roomcad set"), std::string::npos) << run.err;  // the holder
    EXPECT_EQ(test::read_bytes(plan), "{}");
  }
  const test::CommandResult run = run_roomcad({"import", home.string(), "-o", plan.string()});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_TRUE(test::read_plan_at(plan).plan.has_value());
  EXPECT_FALSE(fs::exists(lock_file_of(plan)));  // released, and removed
}

}  // namespace
}  // namespace roomcad
