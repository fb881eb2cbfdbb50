// SPDX-License-Identifier: GPL-3.0-or-later
// The Sweet Home 3D importer on archives and on bad input: a .sh3d built here with libzip
// imports like its bare Home.xml; malformed files give errors naming the file and the problem.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <zip.h>

#include "import/sh3d_test_data.h"
#include "import/sweethome3d_import.h"

namespace roomcad {
namespace {

using namespace sh3d_test;

/// Writes a ZIP archive at `path` with one entry `name` holding `text`.
void write_zip(const fs::path& path, const std::string& name, const std::string& text) {
  int error = 0;
  zip_t* archive = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  ASSERT_NE(archive, nullptr);
  zip_source_t* source = zip_source_buffer(archive, text.data(), text.size(), 0);
  ASSERT_NE(source, nullptr);
  ASSERT_GE(zip_file_add(archive, name.c_str(), source, ZIP_FL_OVERWRITE), 0);
  ASSERT_EQ(zip_close(archive), 0);  // writes the archive; `text` must live until here
}

std::string import_error(const fs::path& path) {
  const Result<Sh3dImport> r = import_sweethome3d_file(path);
  EXPECT_FALSE(r.ok()) << path;
  return r.ok() ? std::string() : r.message();
}

TEST(Sh3dArchive, ImportsLikeItsHomeXml) {
  const test::TempDir dir;
  const fs::path xml = kData / "eteks-example-homes" / "ApartmentWithBowWindow.Home.xml";
  const fs::path sh3d = dir / "Bow.sh3d";
  write_zip(sh3d, "Home.xml", read_text(xml));
  const Sh3dImport from_xml = import_or_fail(xml);
  const Sh3dImport from_zip = import_or_fail(sh3d);
  EXPECT_EQ(from_zip.plan, from_xml.plan);
  EXPECT_EQ(from_zip.warnings.items, from_xml.warnings.items);
  EXPECT_FALSE(from_zip.plan.walls.empty());
}

TEST(Sh3dArchive, ErrorsNameTheFileAndTheProblem) {
  const test::TempDir dir;
  const fs::path not_zip = dir / "text.sh3d";
  ASSERT_TRUE(test::write_bytes(not_zip, "this is not a zip archive"));
  EXPECT_NE(import_error(not_zip).find("text.sh3d: not a readable .sh3d (ZIP) archive"),
            std::string::npos);

  const fs::path no_home = dir / "empty.sh3d";
  write_zip(no_home, "Other.xml", "<home/>");
  EXPECT_NE(import_error(no_home).find("empty.sh3d: the archive has no Home.xml entry"),
            std::string::npos);

  const fs::path missing = dir / "missing.xml";
  EXPECT_NE(import_error(missing).find("missing.xml: cannot open"), std::string::npos);
}

TEST(Sh3dArchive, MalformedXmlIsAnErrorNamingElementAttributeAndValue) {
  const test::TempDir dir;
  struct Case {
    std::string xml;
    std::string expected;
  };
  const Case cases[] = {
      {"<home><wall id='w1'", "bad.xml: malformed XML at byte"},
      {"<plan/>", "bad.xml: not a Sweet Home 3D Home.xml: the root element is <plan>"},
      {"<home><wall id='w1' yStart='0' xEnd='1' yEnd='0' thickness='10'/></home>",
       "<wall id='w1'> attribute 'xStart' is missing"},
      {"<home><wall id='w1' xStart='abc' yStart='0' xEnd='1' yEnd='0' thickness='10'/></home>",
       "<wall id='w1'> attribute 'xStart' is not a finite number: 'abc'"},
      {"<home><wall id='w1' xStart='0' yStart='0' xEnd='1' yEnd='0' thickness='NaN'/></home>",
       "attribute 'thickness' is not a finite number: 'NaN'"},
      {"<home><wall id='w1' level='up' xStart='0' yStart='0' xEnd='1' yEnd='0' "
       "thickness='1'/></home>",
       "<wall id='w1'> attribute 'level' names no <level>: 'up'"},
      {"<home><doorOrWindow id='d' name='Door' x='0' y='0' width='1' depth='1' height='1'/>"
       "</home>",
       "bad.xml: no <wall> to import"},
  };
  for (const Case& c : cases) {
    const fs::path bad = dir / "bad.xml";
    ASSERT_TRUE(test::write_bytes(bad, c.xml));
    EXPECT_NE(import_error(bad).find(c.expected), std::string::npos)
        << c.xml << "\n  gave: " << import_error(bad);
  }
}

TEST(Sh3dArchive, ItemWithNoWallIsSkippedWithAWarningNamingIt) {
  const test::TempDir dir;
  const fs::path home = dir / "lonely.xml";
  ASSERT_TRUE(test::write_bytes(
      home,
      "<home wallHeight='250'><doorOrWindow id='far' name='Window' x='1000' y='1000' "
      "width='100' depth='20' height='100' elevation='90'/>"
      "<wall id='w1' xStart='0' yStart='0' xEnd='400' yEnd='0' thickness='20'/></home>"));
  const Sh3dImport imported = import_or_fail(home);
  EXPECT_TRUE(imported.plan.openings.empty());
  ASSERT_EQ(imported.warnings.items.size(), 1u);
  EXPECT_EQ(imported.warnings.items[0].code, Code::import_skipped_opening);
  EXPECT_EQ(imported.warnings.items[0].objects, std::vector<std::string>{"far"});
  ASSERT_EQ(imported.plan.walls.size(), 1u);
  EXPECT_DOUBLE_EQ(imported.plan.walls[0].height, 2.5);  // the home's default wall height
}

}  // namespace
}  // namespace roomcad
