// SPDX-License-Identifier: GPL-3.0-or-later
// PNG and PFM files and object-id images: round trips, determinism and errors naming the file.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "io/id_image.h"
#include "io/image_io.h"

namespace roomcad {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "roomcad_image_io_test";
  fs::create_directories(dir);
  return dir / name;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

RgbImage gradient(int w, int h) {
  RgbImage image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = image.at(x, y);
      p[0] = static_cast<std::uint8_t>(x * 7);
      p[1] = static_cast<std::uint8_t>(y * 13);
      p[2] = static_cast<std::uint8_t>(x ^ y);
    }
  return image;
}

TEST(ImageIo, PngRoundTripsAndIsDeterministic) {
  const RgbImage image = gradient(37, 21);
  const fs::path a = scratch("a.png"), b = scratch("b.png");
  ASSERT_TRUE(write_png(image, a).ok());
  ASSERT_TRUE(write_png(image, b).ok());
  EXPECT_EQ(read_bytes(a), read_bytes(b));
  const Result<RgbImage> back = read_png(a);
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back.value().width, 37);
  EXPECT_EQ(back.value().height, 21);
  EXPECT_EQ(back.value().pixels, image.pixels);
}

TEST(ImageIo, ErrorsNameTheFileAndLeaveNothing) {
  const fs::path missing_dir = scratch("no_such_dir") / "out.png";
  const Status s = write_png(gradient(4, 4), missing_dir);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("out.png"), std::string::npos) << s.message();
  EXPECT_FALSE(fs::exists(missing_dir));
  EXPECT_FALSE(write_png(RgbImage{}, scratch("empty.png")).ok());
  const fs::path not_png = scratch("not.png");
  std::ofstream(not_png) << "hello";
  const Result<RgbImage> r = read_png(not_png);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.message().find("not.png"), std::string::npos) << r.error();
  EXPECT_FALSE(read_png(scratch("absent.png")).ok());
}

TEST(ImageIo, PfmHasHeaderAndRowsBottomUp) {
  FloatImage depth(3, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) depth.at(x, y) = static_cast<float>(10 * y + x);
  const fs::path path = scratch("d.pfm");
  ASSERT_TRUE(write_pfm(depth, path).ok());
  const std::string bytes = read_bytes(path);
  const std::string header = "Pf\n3 2\n-1.0\n";
  ASSERT_EQ(bytes.size(), header.size() + 6 * sizeof(float));
  EXPECT_EQ(bytes.substr(0, header.size()), header);
  float first = 0.f;
  std::memcpy(&first, bytes.data() + header.size(), sizeof first);
  EXPECT_EQ(first, 10.f);  // the bottom row (y = 1) comes first
}

TEST(ImageIo, ObjectIdsRoundTripThroughPngAndLegend) {
  ObjectIdImage ids{.width = 2, .height = 2, .ids = {-1, 0, 1, 300}};
  const fs::path png = scratch("ids.png");
  std::vector<std::string> objects(301, "o");
  objects[1] = "wall \"one\"";
  ASSERT_TRUE(write_object_ids(ids, objects, png).ok());
  const Result<RgbImage> back = read_png(png);
  ASSERT_TRUE(back.ok());
  auto decode = [&](int i) {
    const std::uint8_t* p = &back.value().pixels[3 * i];
    return static_cast<int>(p[0] + 256 * p[1] + 65536 * p[2]) - 1;
  };
  for (int i = 0; i < 4; ++i) EXPECT_EQ(decode(i), ids.ids[i]);
  EXPECT_EQ(legend_path(png), scratch("ids.json"));
  const std::string legend = read_bytes(scratch("ids.json"));
  EXPECT_NE(legend.find(R"("id": "wall \"one\"")"), std::string::npos) << legend;
  EXPECT_NE(legend.find(R"("color": "#020000")"), std::string::npos);
}

}  // namespace
}  // namespace roomcad
