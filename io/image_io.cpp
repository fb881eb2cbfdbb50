// SPDX-License-Identifier: GPL-3.0-or-later
// PNG through libpng's memory interface (encode into a string, then one atomic write), and PFM.
#include "io/image_io.h"

#include <png.h>

#include <bit>
#include <csetjmp>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include <fmt/format.h>

#include "io/atomic_write.h"

namespace roomcad {
namespace {

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), length);
}

void flush_nothing(png_structp) {}

/// Encodes an RGB image as PNG bytes. No time stamp or text chunk, so the bytes depend only
/// on the pixels. @return false (and sets `error`) if libpng fails.
bool encode_png(const RgbImage& image, std::string& out, std::string& error) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    error = "libpng could not allocate its encoder";
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {  // libpng reports errors by longjmp
    png_destroy_write_struct(&png, &info);
    error = "libpng failed to encode the image";
    return false;
  }
  png_set_write_fn(png, &out, append_bytes, flush_nothing);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) {
    png_write_row(png, const_cast<png_bytep>(image.at(0, y)));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

/// Decodes PNG bytes with libpng's simplified API, converting any format to 8-bit RGB.
Result<RgbImage> decode_png(std::string_view bytes, std::string_view file) {
  png_image header;
  std::memset(&header, 0, sizeof header);
  header.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&header, bytes.data(), bytes.size())) {
    return Result<RgbImage>::failure(
        Code::unsupported,
        fmt::format("read_png: '{}' is not a PNG file: {}", file, header.message));
  }
  if (header.width > kMaxPngSide || header.height > kMaxPngSide ||
      static_cast<long long>(header.width) * header.height > kMaxPngPixels) {
    png_image_free(&header);
    return Result<RgbImage>::failure(
        Code::too_large,
        fmt::format("read_png: '{}' is {} x {} pixels; at most {} per side and {} in all are read",
                    file, header.width, header.height, kMaxPngSide, kMaxPngPixels));
  }
  header.format = PNG_FORMAT_RGB;  // drops alpha, expands grey and palettes
  RgbImage image(static_cast<int>(header.width), static_cast<int>(header.height));
  if (!png_image_finish_read(&header, nullptr, image.pixels.data(), 0, nullptr)) {
    png_image_free(&header);
    return Result<RgbImage>::failure(
        Code::parse_error,
        fmt::format("read_png: '{}' could not be decoded: {}", file, header.message));
  }
  return image;
}

}  // namespace

Result<std::string> png_bytes(const RgbImage& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    return Result<std::string>::failure(
        Code::precondition, fmt::format("image is {} x {} with {} bytes", image.width, image.height,
                                        image.pixels.size()));
  }
  std::string bytes;
  std::string error;
  if (!encode_png(image, bytes, error)) return Result<std::string>::failure(Code::io_error, error);
  return bytes;
}

Status write_png(const RgbImage& image, const std::filesystem::path& path) {
  const Result<std::string> bytes = png_bytes(image);
  if (!bytes)
    return Status::failure(bytes.code(),
                           fmt::format("write_png: '{}': {}", path.string(), bytes.message()));
  return write_file_atomically(path, bytes.value());
}

Result<RgbImage> read_png(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    return Result<RgbImage>::failure(
        Code::io_error, fmt::format("read_png: cannot open '{}' for reading", path.string()));
  }
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return decode_png(bytes, path.string());
}

Result<RgbImage> read_png_bytes(std::string_view bytes, std::string_view file) {
  return decode_png(bytes, file);
}

Status write_pfm(const FloatImage& image, const std::filesystem::path& path) {
  if (image.width <= 0 || image.height <= 0 ||
      image.values.size() != static_cast<std::size_t>(image.width) * image.height) {
    return Status::failure(
        Code::precondition,
        fmt::format("write_pfm: '{}': image is {} x {} with {} values", path.string(), image.width,
                    image.height, image.values.size()));
  }
  // A negative scale means little-endian; rows go bottom-up.
  std::string bytes = fmt::format("Pf\n{} {}\n-1.0\n", image.width, image.height);
  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * sizeof(float);
  static_assert(sizeof(float) == 4 && std::endian::native == std::endian::little,
                "PFM is written as little-endian IEEE single floats");
  for (int y = image.height - 1; y >= 0; --y) {
    const char* row =
        reinterpret_cast<const char*>(&image.values[static_cast<std::size_t>(y) * image.width]);
    bytes.append(row, row_bytes);
  }
  return write_file_atomically(path, bytes);
}

}  // namespace roomcad
