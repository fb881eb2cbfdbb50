// SPDX-License-Identifier: GPL-3.0-or-later
// Limits on hostile input: every reader refuses what would exhaust memory or time with an error
// naming the file, the field and the value, and reports many problems in linear time.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "io/detail/plan_reader.h"
#include "io/detail/positioned_json.h"
#include "io/image_io.h"
#include "io/plan_json.h"
#include "io/text_file.h"
#include "support/plan_reading.h"
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

TEST(HostileInput, TooManyObjectsIsAnInvalidValueNamingTheArrayAndCount) {
  std::string text = R"({"format": "roomcad-plan", "version": 1, "walls": [0)";
  for (std::size_t i = 0; i < kMaxPlanObjects; ++i) text += ",0";
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
  ASSERT_TRUE(test::make_sparse_file(dir / "big.json", kMaxTextFileBytes + 1));
  const std::string why = ": it is 268435457 bytes; files of at most 268435456 bytes (256 MiB)";
  const Result<Plan> plan = read_plan_file(dir / "big.json");
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.code(), Code::too_large);
  EXPECT_NE(plan.message().find("big.json" + why), std::string::npos) << plan.error();
  // The command exits 2 (could not run), naming the file.
  const auto r = test::run_roomcad({"info", (dir / "big.json").string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(test::failure_code(r), Code::too_large);
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
