// Image files: PNG (libpng) and PFM (portable float map, for depth buffers). Written atomically.
#pragma once

#include <filesystem>

#include "io/result.h"
#include "render/image.h"

namespace roomcad {

/// Writes an 8-bit RGB PNG. Deterministic: the same image gives the same bytes.
Status write_png(const RgbImage& image, const std::filesystem::path& path);

/// Reads an 8-bit RGB or RGBA PNG (alpha dropped); errors name the file and the reason.
[[nodiscard]] Result<RgbImage> read_png(const std::filesystem::path& path);

/// Writes a little-endian PFM (greyscale, "Pf"), rows bottom-up as the format requires.
Status write_pfm(const FloatImage& image, const std::filesystem::path& path);

}  // namespace roomcad
