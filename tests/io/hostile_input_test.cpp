// Limits on hostile input: every reader refuses what would exhaust memory or time with an error
// naming the file, the field and the value, and reports many problems in linear time.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "support/plan_reading.h"
#include "io/detail/plan_reader.h"
#include "io/detail/sh3d_arcs.h"
#include "io/detail/positioned_json.h"
#include "io/image_io.h"
#include "io/plan_json.h"
#include "io/sweethome3d_import.h"
#include "io/text_file.h"
#include "support/run_command.h"

namespace roomcad {
namespace {

/// Appends a PNG chunk: length, type, data and the CRC-32 of type and data.
void append_chunk(std::string& out, const std::string& type, const std::string& data) {
  auto be32 = [&out](std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>((v >> shift) & 0xff);
  };
  be32(static_cast<std::uint32_t>(data.size()));
  std::uint32_t crc = 0xffffffffu;
  for (const char c : type + data) {
    crc ^= static_cast<unsigned char>(c);
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  out += type + data;
  be32(~crc);
}

/// A PNG claiming `width` x `height` 8-bit RGB pixels and holding no pixel data: the header
/// reads, and allocating the image is the next step.
std::string png_claiming(std::uint32_t width, std::uint32_t height) {
  std::string ihdr;
  for (const std::uint32_t v : {width, height})
    for (int shift = 24; shift >= 0; shift -= 8) ihdr += static_cast<char>((v >> shift) & 0xff);
  ihdr += std::string("\x08\x02\x00\x00\x00", 5);  // 8-bit RGB, no interlace
  std::string png = "\x89PNG\r\n\x1a\n";
  append_chunk(png, "IHDR", ihdr);
  append_chunk(png, "IDAT", "");
  append_chunk(png, "IEND", "");
  return png;
}

TEST(HostileInput, PngClaimingAHugeImageIsRefusedBeforeAllocation) {
  const Result<RgbImage> huge = read_png_bytes(png_claiming(100000, 100000), "huge.png");
  ASSERT_FALSE(huge.ok());
  EXPECT_NE(huge.message().find("'huge.png' is 100000 x 100000 pixels"), std::string::npos)
      << huge.error();
  // One side over the limit, the area within it: still refused.
  EXPECT_FALSE(read_png_bytes(png_claiming(kMaxPngSide + 1, 1), "wide.png").ok());
  // At the limit the header passes the size check and fails only for the missing data.
  const Result<RgbImage> side = read_png_bytes(png_claiming(kMaxPngSide, 1), "side.png");
  ASSERT_FALSE(side.ok());
  EXPECT_NE(side.message().find("could not be decoded"), std::string::npos) << side.error();
}

TEST(HostileInput, Sh3dArchiveDeclaringAHugeHomeXmlIsRefused) {
  // 172 bytes whose Home.xml entry claims 4294967280 bytes (fuzz/corpus/sh3d_archive).
  const auto archive = test::source_dir() / "fuzz/corpus/sh3d_archive/huge-entry.sh3d";
  const Result<Sh3dImport> imported = import_sweethome3d_file(archive);
  ASSERT_FALSE(imported.ok());
  EXPECT_NE(imported.message().find("huge-entry.sh3d: its Home.xml entry is 4294967280 bytes"),
            std::string::npos)
      << imported.error();
}

TEST(HostileInput, Sh3dHomeWithTooManyWallItemPairsIsRefusedBeforeMatching) {
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

TEST(HostileInput, Sh3dHomeWithMoreWallsThanAPlanHoldsIsRefused) {
  // A plan the reader refuses (io_detail::kMaxPlanObjects) must not be written by import.
  std::string xml = "<home version='6500'>";
  xml.reserve(100 * (io_detail::kMaxPlanObjects + 1));
  for (std::size_t i = 0; i <= io_detail::kMaxPlanObjects; ++i)
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

TEST(HostileInput, Sh3dHomeSpreadBeyondAnySiteIsRefused) {
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

TEST(HostileInput, Sh3dHomeWhoseWallsAllHaveZeroLengthIsRefused) {
  // Found by fuzz_sh3d_archive (fuzz/corpus/sh3d_archive/crash-zero-length-walls.sh3d): with
  // every wall left out, the site was made from an empty box and its cell count overflowed.
  const std::string xml =
      "<home><wall id='a' xStart='400' yStart='0' xEnd='400' yEnd='0' thickness='10' "
      "height='250'/><wall id='b' xStart='1' yStart='2' xEnd='1' yEnd='2' thickness='10' "
      "height='250'/></home>";
  const Result<Sh3dImport> imported = import_sweethome3d_text(xml, "dots.Home.xml");
  ASSERT_FALSE(imported.ok());
  EXPECT_EQ(imported.code(), Code::invalid_value);
  EXPECT_EQ(imported.message(), "dots.Home.xml: no wall to import: each of its 2 <wall> elements "
                                "starts and ends at the same point");
  const auto found = test::source_dir() / "fuzz/corpus/sh3d_archive/crash-zero-length-walls.sh3d";
  const Result<Sh3dImport> again = import_sweethome3d_file(found);
  ASSERT_FALSE(again.ok());
  EXPECT_NE(again.message().find("no wall to import"), std::string::npos) << again.error();
}

TEST(HostileInput, Sh3dTEndsThatCannotMoveAreNeitherMovedNorReported) {
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

TEST(HostileInput, ArcWithAToleranceBelowItsRoundingGetsBoundedChords) {
  // 1 - tolerance / radius rounds to 1: the chord angle is 0 and the chord count infinite.
  const std::vector<Point2> points = sh3d::split_arc({0, 0}, {1e9, 0}, 1.0, 1e-12);
  ASSERT_GE(points.size(), 2u);
  EXPECT_LE(points.size(), 257u);
  EXPECT_EQ(points.front(), (Point2{0, 0}));
  EXPECT_EQ(points.back(), (Point2{1e9, 0}));
  for (const Point2 p : points) EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
}

TEST(HostileInput, TooManyObjectsIsAnInvalidValueNamingTheArrayAndCount) {
  std::string text = R"({"format": "roomcad-plan", "version": 1, "walls": [0)";
  for (std::size_t i = 0; i < io_detail::kMaxPlanObjects; ++i) text += ",0";
  text += "]}";
  const test::PlanReading read = test::read_plan(text, "many.json");
  ASSERT_FALSE(read.plan);
  ASSERT_EQ(read.report.items.size(), 1u);
  const Diagnostic& d = read.report.items[0];
  EXPECT_EQ(d.code, Code::invalid_value);
  EXPECT_EQ(d.message,
            "many.json:1:51: /walls: 1000001 objects; a plan may hold at most 1000000 of each "
            "kind (levels, walls, openings, slabs, lights, cameras)");
}

TEST(HostileInput, FilesOverTheSizeLimitAreRefusedUnread) {
  test::TempDir dir;
  for (const char* name : {"big.json", "big.Home.xml"}) {
    std::FILE* file = std::fopen((dir / name).c_str(), "wb");
    ASSERT_NE(file, nullptr);
    // Sparse: no disk space used, and the readers must not read it anyway.
    ASSERT_EQ(::ftruncate(::fileno(file), static_cast<off_t>(kMaxTextFileBytes + 1)), 0);
    std::fclose(file);
  }
  const std::string why = ": it is 268435457 bytes; files of at most 268435456 bytes (256 MiB)";
  const Result<Plan> plan = read_plan_file(dir / "big.json");
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.code(), Code::too_large);
  EXPECT_NE(plan.message().find("big.json" + why), std::string::npos) << plan.error();
  const Result<Sh3dImport> home = import_sweethome3d_file(dir / "big.Home.xml");
  ASSERT_FALSE(home.ok());
  EXPECT_EQ(home.code(), Code::too_large);
  EXPECT_NE(home.message().find("big.Home.xml" + why), std::string::npos) << home.error();
  // The command exits 2 (could not run), naming the file.
  const auto r = test::run_roomcad({"info", (dir / "big.json").string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("big.json" + why), std::string::npos) << r.err;
}

TEST(HostileInput, ManyProblemsOnOneLineGetTheirOwnColumns) {
  // A minified file full of errors: each is located by scanning on from the previous one.
  std::string text = R"({"format": "roomcad-plan", "version": 1, "walls": [)";
  const std::size_t n = 2000;
  for (std::size_t i = 0; i < n; ++i) text += std::string(i ? "," : "") + R"({"id": "é", "x": 1})";
  text += "]}";
  const test::PlanReading read = test::read_plan(text, "one-line.json");
  ASSERT_FALSE(read.plan);
  std::size_t unknown = 0;
  for (const Diagnostic& d : read.report.items) {
    if (d.code != Code::unknown_field) continue;
    ASSERT_TRUE(d.location);
    // Wall i starts at column 52 + 20 i ("é" is one character); its key "x" 12 further on.
    EXPECT_EQ(d.location->line, 1u);
    EXPECT_EQ(d.location->column, 52 + 20 * unknown + 12) << d.message;
    ++unknown;
  }
  EXPECT_EQ(unknown, n);
}

TEST(HostileInput, LineColumnCursorMatchesLineColumnAtInAnyOrder) {
  const std::string text = "ab\ncdé\n\nfgh";
  io_detail::LineColumnCursor cursor(text);
  for (const std::size_t offset : {0u, 4u, 7u, 2u, 11u, 50u, 3u, 3u}) {
    const io_detail::LineColumn expected = io_detail::line_column_at(text, offset);
    const io_detail::LineColumn got = cursor.at(offset);
    EXPECT_EQ(got.line, expected.line) << offset;
    EXPECT_EQ(got.column, expected.column) << offset;
  }
}

}  // namespace
}  // namespace roomcad
