// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the PNG reader (io/image_io.h) on arbitrary bytes. Any crash, sanitizer
// report, leak or hang is a bug, and so is an image whose buffer does not match its size.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const roomcad::Result<roomcad::RgbImage> image = roomcad::read_png_bytes(bytes, "fuzz.png");
  if (!image) return 0;
  const roomcad::RgbImage& rgb = image.value();
  if (rgb.width <= 0 || rgb.height <= 0 ||
      rgb.pixels.size() != static_cast<std::size_t>(rgb.width) * rgb.height * 3)
    __builtin_trap();
  return 0;
}
