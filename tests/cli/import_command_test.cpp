// `roomcad import` run as a program: exit statuses, the plan file it writes, its messages.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "io/plan_json.h"
#include "io/sweethome3d_import.h"

namespace roomcad {
namespace {

namespace fs = std::filesystem;

const fs::path kHomes =
    fs::path(ROOMCAD_SOURCE_DIR) / ".." / "shared" / "realdata" / "sweethome3d";

struct Run {
  int status = -1;
  std::string err;
};

/// Runs `roomcad <args>` through the shell, capturing its standard error.
Run run_roomcad(const std::string& args, const fs::path& scratch) {
  const fs::path err = scratch / "stderr.txt";
  const std::string command = std::string(ROOMCAD_EXE) + " " + args + " 2> " + err.string();
  const int raw = std::system(command.c_str());
  std::ifstream in(err);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, text.str()};
}

struct Scratch {
  fs::path path = fs::temp_directory_path() /
                  ("roomcad-import-cli-" +
                   std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  Scratch() { fs::create_directories(path); }
  ~Scratch() { fs::remove_all(path); }
};

TEST(ImportCommand, WritesThePlanTheImporterBuilds) {
  const Scratch scratch;
  const fs::path home = kHomes / "eteks-example-homes" / "1-BedroomApartment.Home.xml";
  const fs::path plan = scratch.path / "apartment.json";
  const Run run = run_roomcad("import " + home.string() + " -o " + plan.string(), scratch.path);
  ASSERT_EQ(run.status, 0) << run.err;
  // The curved wall is announced by id.
  EXPECT_NE(run.err.find("warning [import_curved_wall]: curved wall 'wall7'"), std::string::npos)
      << run.err;
  const PlanReadResult read = read_plan_file(plan);
  ASSERT_TRUE(read.plan.has_value());
  EXPECT_TRUE(read.report.ok());
  const Result<Sh3dImport> imported = import_sweethome3d_file(home);
  ASSERT_TRUE(imported.ok());
  EXPECT_EQ(*read.plan, imported.value().plan);
}

TEST(ImportCommand, BadInputExitsTwoNamingTheFileAndWritesNothing) {
  const Scratch scratch;
  const fs::path bad = scratch.path / "broken.xml";
  std::ofstream(bad) << "<home><wall id='w'";
  const fs::path plan = scratch.path / "out.json";
  Run run = run_roomcad("import " + bad.string() + " -o " + plan.string(), scratch.path);
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("broken.xml: malformed XML"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(plan));

  run = run_roomcad("import " + (scratch.path / "absent.sh3d").string() + " -o " + plan.string(),
                    scratch.path);
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("absent.sh3d"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(plan));

  run = run_roomcad("import " + (kHomes / "edge-cases" / "Sample.Home.xml").string() +
                        " -o " + plan.string() + " --level Attic",
                    scratch.path);
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("--level 'Attic' names no level"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(plan));
}

TEST(ImportCommand, UnwritableOutputExitsTwo) {
  const Scratch scratch;
  const fs::path home = kHomes / "eteks-example-homes" / "Studio.Home.xml";
  const Run run = run_roomcad(
      "import " + home.string() + " -o " + (scratch.path / "no-such-dir" / "p.json").string(),
      scratch.path);
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("no-such-dir"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace roomcad
