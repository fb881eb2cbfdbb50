// SPDX-License-Identifier: GPL-3.0-or-later
// Limits on hostile Sweet Home 3D input: the importer refuses what would exhaust memory or time
// with an error naming the file, the field and the value (most found by fuzz/fuzz_sh3d_*).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "import/sweethome3d_import.h"
#include "io/plan_json.h"
#include "io/text_file.h"
#include "support/run_command.h"

namespace roomcad {
namespace {

TEST(HostileSh3d, Sh3dArchiveDeclaringAHugeHomeXmlIsRefused) {
  // 172 bytes whose Home.xml entry claims 4294967280 bytes (fuzz/corpus/sh3d_archive).
  const auto archive = test::source_dir() / "fuzz/corpus/sh3d_archive/huge-entry.sh3d";
  const Result<Sh3dImport> imported = import_sweethome3d_file(archive);
  ASSERT_FALSE(imported.ok());
  EXPECT_NE(imported.message().find("huge-entry.sh3d: its Home.xml entry is 4294967280 bytes"),
            std::string::npos)
      << imported.error();
}

TEST(HostileSh3d, Sh3dHomeWithTooManyWallItemPairsIsRefusedBeforeMatching) {
  std::string xml = "<home version='6500'>";
  for (int i = 0; i < 50000; ++i)
    xml += "<wall id='w" + std::to_string(i) + "' xStart='0' yStart='" + std::to_string(i) +
           "' xEnd='100' yEnd='" + std::to_string(i) + "' thickness='10' height='250'/>";
  for (int i = 0; i < 20001; ++i)
    xml += "<doorOrWindow id='d" + std::to_string(i) +
           "' x='50' y='0' elevation='0' width='90' depth='10' height='210' angle='0'/>";
  xml += "</home>";
  const Result<Sh3dImport> imported = import_sweethome3d_text(xml, "crowded.Home.xml");
  ASSERT_FALSE(imported.ok());
  EXPECT_NE(imported.message().find("crowded.Home.xml: 50000 <wall> and 20001 <doorOrWindow> and "
                                    "<level> elements; at most 1000000000 pairs"),
            std::string::npos)
      << imported.error();
}

TEST(HostileSh3d, Sh3dHomeWithMoreWallsThanAPlanHoldsIsRefused) {
  // A plan the reader refuses (kMaxPlanObjects) must not be written by import.
  std::string xml = "<home version='6500'>";
  xml.reserve(100 * (kMaxPlanObjects + 1));
  for (std::size_t i = 0; i <= kMaxPlanObjects; ++i)
    xml += "<wall id='w" + std::to_string(i) +
           "' xStart='0' yStart='0' xEnd='100' yEnd='0' thickness='10' height='250'/>";
  xml += "</home>";
  const Result<Sh3dImport> imported = import_sweethome3d_text(xml, "huge.Home.xml");
  ASSERT_FALSE(imported.ok());
  EXPECT_NE(imported.message().find("huge.Home.xml: 1000001 <wall> and 0 <doorOrWindow> elements; "
                                    "a plan may hold at most 1000000 of each kind"),
            std::string::npos)
      << imported.error();
}

TEST(HostileSh3d, Sh3dHomeSpreadBeyondAnySiteIsRefused) {
  // Found by fuzz_sh3d_xml (fuzz/corpus/sh3d_xml/crash-site-cells.Home.xml): the cell count of
  // a site 3.5e115 m wide overflowed its integer.
  const std::string xml =
      "<home><wall id='w' xStart='0' yStart='0' xEnd='3.5e117' yEnd='0' thickness='10' "
      "height='250'/></home>";
  const Result<Sh3dImport> imported = import_sweethome3d_text(xml, "far.Home.xml");
  ASSERT_FALSE(imported.ok());
  EXPECT_NE(imported.message().find("far.Home.xml: the walls span 3.5e+115 m, more than 1e+09 "
                                    "cells of 1 m"),
            std::string::npos)
      << imported.error();
  const auto found = test::source_dir() / "fuzz/corpus/sh3d_xml/crash-site-cells.Home.xml";
  const Result<Sh3dImport> again = import_sweethome3d_file(found);
  ASSERT_FALSE(again.ok());
  EXPECT_NE(again.message().find("more than 1e+09 cells"), std::string::npos) << again.error();
}

TEST(HostileSh3d, CutOutArcOfAHugeRadiusIsBoundedNotOverflowed) {
  // Found by fuzz_sh3d_xml (fuzz/corpus/sh3d_xml/crash-cut-out-arc-radius-far-above-tolerance):
  // an arc of radius 4.4e30 wanted infinitely many chords, cast to int (undefined; the
  // sanitized build stops on it). The fuzzer also wrote bytes 0xFF into a door's id, which no
  // XML may hold: the file is refused for them, and with them made ASCII its opening is
  // imported, its outline bounded.
  const auto found = test::source_dir() /
                     "fuzz/corpus/sh3d_xml/crash-cut-out-arc-radius-far-above-tolerance.Home.xml";
  const Result<Sh3dImport> refused = import_sweethome3d_file(found);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.code(), Code::parse_error);
  EXPECT_NE(refused.message().find("> attribute 'id' is not UTF-8 (byte 47 is 0xFF): "
                                   "'doorOrWindow-846fb04e-4cac-4275-b024-591a74b3e\\xFF\\xFF"),
            std::string::npos)
      << refused.error();

  std::string xml = read_text_file(found).value();
  std::replace(xml.begin(), xml.end(), '\xff', 'f');
  const Result<Sh3dImport> imported = import_sweethome3d_text(xml, "arc.Home.xml");
  ASSERT_TRUE(imported.ok()) << imported.error();
  EXPECT_EQ(imported.value().plan.walls.size(), 43u);
  EXPECT_EQ(imported.value().plan.openings.size(), 20u);
}

TEST(HostileSh3d, IllFormedUtf8InAnAttributeIsRefusedNamingIt) {
  // A plan is UTF-8: an ill-formed byte copied into an id would make the written plan
  // unreadable. Latin-1 that the XML declares as such is converted by the XML reader.
  const std::string latin1_wall =
      "<wall id='K\xfc"
      "che' xStart='0' yStart='0' xEnd='400' yEnd='0' "
      "thickness='10' height='250'/>";
  const Result<Sh3dImport> refused =
      import_sweethome3d_text("<home>" + latin1_wall + "</home>", "k.Home.xml");
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.code(), Code::parse_error);
  EXPECT_EQ(refused.message(),
            "k.Home.xml: <wall id='K\\xFCche'> attribute 'id' is not UTF-8 "
            "(byte 2 is 0xFC): 'K\\xFCche'");

  const Result<Sh3dImport> declared = import_sweethome3d_text(
      "<?xml version='1.0' encoding='ISO-8859-1'?><home>" + latin1_wall + "</home>", "k.Home.xml");
  ASSERT_TRUE(declared.ok()) << declared.error();
  ASSERT_EQ(declared.value().plan.walls.size(), 1u);
  EXPECT_EQ(declared.value().plan.walls[0].id,
            "K\xc3\xbc"
            "che");
}

TEST(HostileSh3d, Sh3dHomeWhoseWallsAllHaveZeroLengthIsRefused) {
  // Found by fuzz_sh3d_archive (fuzz/corpus/sh3d_archive/crash-zero-length-walls.sh3d): with
  // every wall left out, the site was made from an empty box and its cell count overflowed.
  const std::string xml =
      "<home><wall id='a' xStart='400' yStart='0' xEnd='400' yEnd='0' thickness='10' "
      "height='250'/><wall id='b' xStart='1' yStart='2' xEnd='1' yEnd='2' thickness='10' "
      "height='250'/></home>";
  const Result<Sh3dImport> imported = import_sweethome3d_text(xml, "dots.Home.xml");
  ASSERT_FALSE(imported.ok());
  EXPECT_EQ(imported.code(), Code::invalid_value);
  EXPECT_EQ(imported.message(),
            "dots.Home.xml: no wall to import: each of its 2 <wall> elements "
            "starts and ends at the same point");
  const auto found = test::source_dir() / "fuzz/corpus/sh3d_archive/crash-zero-length-walls.sh3d";
  const Result<Sh3dImport> again = import_sweethome3d_file(found);
  ASSERT_FALSE(again.ok());
  EXPECT_NE(again.message().find("no wall to import"), std::string::npos) << again.error();
}

TEST(HostileSh3d, Sh3dTEndsThatCannotMoveAreNeitherMovedNorReported) {
  // Found by fuzz_sh3d_archive (fuzz/corpus/sh3d_archive/crash-t-join-kept.sh3d): ends inside
  // another wall whose move would change a wall's length stay put, but were listed as moved,
  // and the warning then named its first object from an empty list (undefined behaviour).
  const std::string xml =
      "<home><level id='l0' name='Ground' elevation='0' height='250'/>"
      "<wall id='w0' level='l0' xStart='199' yStart='0' xEnd='400' yEnd='0' height='249' "
      "thickness='10'/><wall id='w2' level='l0' xStart='401' yStart='0' xEnd='400' yEnd='0' "
      "height='250' thickness='10'/><wall id='w3' level='l0' xStart='401' yStart='0' "
      "xEnd='400' yEnd='2' height='250' thickness='10'/></home>";
  for (const Result<Sh3dImport>& imported :
       {import_sweethome3d_text(xml, "kept.Home.xml"),
        import_sweethome3d_file(test::source_dir() /
                                "fuzz/corpus/sh3d_archive/crash-t-join-kept.sh3d")}) {
    ASSERT_TRUE(imported.ok()) << imported.error();
    for (const Diagnostic& d : imported.value().warnings.items) {
      if (d.code == Code::import_t_junction) {
        EXPECT_FALSE(d.objects.empty()) << d.message;
      }
    }
  }
}

TEST(HostileSh3d, FilesOverTheSizeLimitAreRefusedUnread) {
  test::TempDir dir;
  ASSERT_TRUE(test::make_sparse_file(dir / "big.Home.xml", kMaxTextFileBytes + 1));
  const Result<Sh3dImport> home = import_sweethome3d_file(dir / "big.Home.xml");
  ASSERT_FALSE(home.ok());
  EXPECT_EQ(home.code(), Code::too_large);
  EXPECT_NE(home.message().find("big.Home.xml: it is 268435457 bytes; files of at most "
                                "268435456 bytes (256 MiB)"),
            std::string::npos)
      << home.error();
}

}  // namespace
}  // namespace roomcad
