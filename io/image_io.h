// SPDX-License-Identifier: GPL-3.0-or-later
// Image files: PNG (libpng) and PFM (portable float map, for depth buffers). Written atomically.
#pragma once

#include <filesystem>
#include <string_view>

#include "core/error.h"
#include "render/image.h"

namespace roomcad {

/// Writes an 8-bit RGB PNG. Deterministic: the same image gives the same bytes.
Status write_png(const RgbImage& image, const std::filesystem::path& path);

/// @return the bytes write_png writes, or an error (an empty or inconsistent image).
[[nodiscard]] Result<std::string> png_bytes(const RgbImage& image);

/// Largest PNG read_png accepts, pixels per side and in all: a 40-byte header can claim
/// 2^31 x 2^31 pixels, and the image is allocated before the data is seen to be missing.
inline constexpr int kMaxPngSide = 16384;
inline constexpr long long kMaxPngPixels = 1LL << 26;  // 64 Mpixel, 192 MiB of RGB

/// Reads an 8-bit RGB or RGBA PNG (alpha dropped); errors name the file and the reason.
/// An image wider or taller than kMaxPngSide, or of more than kMaxPngPixels, is an error.
[[nodiscard]] Result<RgbImage> read_png(const std::filesystem::path& path);

/// The same for the bytes of a PNG file; `file` names it in errors. O(bytes + pixels).
[[nodiscard]] Result<RgbImage> read_png_bytes(std::string_view bytes, std::string_view file);

/// Writes a little-endian PFM (greyscale, "Pf"), rows bottom-up as the format requires.
Status write_pfm(const FloatImage& image, const std::filesystem::path& path);

}  // namespace roomcad
