// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/svg_writer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace roomcad {
namespace {

TEST(SvgWriter, FormatsNumbersWithAtMostThreeDecimals) {
  EXPECT_EQ(format_svg_number(0.0), "0");
  EXPECT_EQ(format_svg_number(-0.0), "0");
  EXPECT_EQ(format_svg_number(-0.0004), "0");
  EXPECT_EQ(format_svg_number(12.5), "12.5");
  EXPECT_EQ(format_svg_number(1.0 / 3.0), "0.333");
  EXPECT_EQ(format_svg_number(-2.0005001), "-2.001");
  EXPECT_EQ(format_svg_number(1200.0), "1200");
}

TEST(SvgWriter, EscapesText) {
  EXPECT_EQ(escape_xml("a<b & \"c\" 'd'>"), "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;");
}

SvgDocument sample_document() {
  SvgDocument doc(210, 297);
  doc.set_title("Plan <ground floor>");
  doc.begin_group("walls", "cut", {.stroke = "#000", .stroke_width = 0.5});
  const std::vector<Point2> square{{10, 10}, {20, 10}, {20, 20}, {10, 20}};
  doc.add_polygon(square, {.fill = "#888"});
  doc.end_group();
  doc.add_line({0, 0}, {1.23456, 2}, {.stroke = "red", .dashes = {2, 1}});
  doc.add_polyline(square, {.stroke = "blue"});
  doc.add_path(SvgPath().move_to({0, 0}).line_to({10, 0}).arc_to(10, 10, 0, false, true, {0, 10}),
               {.stroke = "#000"});
  doc.add_rect({1, 2}, 3, 4, {.stroke = "#000", .fill = "none"});
  doc.add_circle({5, 5}, 1.5);
  doc.add_text({50, 60}, "Kitchen 12.5 m²", {.size = 3, .anchor = "middle", .rotate_deg = -90});
  return doc;
}

TEST(SvgWriter, WritesTheElementsAsAsked) {
  const std::string text = sample_document().to_string();
  const auto has = [&](const std::string& s) { return text.find(s) != std::string::npos; };
  EXPECT_EQ(text.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg ", 0), 0u);
  EXPECT_TRUE(has("width=\"210mm\" height=\"297mm\" viewBox=\"0 0 210 297\""));
  EXPECT_TRUE(has("<title>Plan &lt;ground floor&gt;</title>"));
  EXPECT_TRUE(
      has("<g id=\"walls\" class=\"cut\" stroke=\"#000\" stroke-width=\"0.5\">\n"
          "<polygon points=\"10,10 20,10 20,20 10,20\" fill=\"#888\"/>\n</g>\n"));
  EXPECT_TRUE(
      has("<line x1=\"0\" y1=\"0\" x2=\"1.235\" y2=\"2\" stroke=\"red\" "
          "stroke-dasharray=\"2 1\"/>"));
  EXPECT_TRUE(has("<polyline points=\"10,10 20,10 20,20 10,20\" stroke=\"blue\" fill=\"none\"/>"));
  EXPECT_TRUE(has("<path d=\"M0,0 L10,0 A10,10 0 0 1 0,10\" stroke=\"#000\" fill=\"none\"/>"));
  EXPECT_TRUE(
      has("<rect x=\"1\" y=\"2\" width=\"3\" height=\"4\" stroke=\"#000\" fill=\"none\"/>"));
  EXPECT_TRUE(has("<circle cx=\"5\" cy=\"5\" r=\"1.5\"/>"));
  EXPECT_TRUE(
      has("text-anchor=\"middle\" fill=\"#000\" transform=\"rotate(-90 50 60)\">"
          "Kitchen 12.5 m²</text>"));
  EXPECT_EQ(text.substr(text.size() - 7), "</svg>\n");
}

TEST(SvgWriter, ClosesOpenGroupsAndIsDeterministic) {
  SvgDocument doc(10, 10);
  doc.begin_group("a");
  doc.begin_group("b");
  doc.end_group();
  const std::string text = doc.to_string();
  EXPECT_NE(text.find("<g id=\"a\">\n<g id=\"b\">\n</g>\n</g>\n</svg>"), std::string::npos) << text;
  EXPECT_EQ(sample_document().to_string(), sample_document().to_string());
}

TEST(SvgWriter, WritesFilesAtomicallyAndReportsFailures) {
  const auto dir = std::filesystem::temp_directory_path() / "roomcad_svg_writer_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto path = dir / "out.svg";
  ASSERT_TRUE(write_svg(sample_document(), path).ok());
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  EXPECT_EQ(bytes.str(), sample_document().to_string());
  const Status failed = write_svg(sample_document(), dir / "missing" / "out.svg");
  EXPECT_FALSE(failed.ok());
  EXPECT_NE(failed.message().find("out.svg"), std::string::npos) << failed.message();
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace roomcad
