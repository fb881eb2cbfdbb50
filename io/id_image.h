// SPDX-License-Identifier: GPL-3.0-or-later
// Object-id images: the renderer's per-pixel object indices as a lossless PNG plus a JSON
// legend, for tests and other tools (`roomcad render --ids OUT.png`).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "render/image.h"
#include "render/renderer.h"

namespace roomcad {

/// Encodes object indices as colours: index i becomes the 24-bit number i + 1, red the low
/// byte, then green, then blue; black (0) is background or a face without an object.
/// @return an image of the same size. O(pixels).
[[nodiscard]] RgbImage encode_object_ids(const ObjectIdImage& ids);

/// @return where write_object_ids puts the legend of `png`: the same name ending in .json
///         (or .legend.json when `png` itself ends in .json).
[[nodiscard]] std::filesystem::path legend_path(const std::filesystem::path& png);

/// Writes encode_object_ids(ids) as a PNG and, beside it (legend_path), the legend:
/// {"encoding": ..., "objects": [{"index": i, "id": objects[i], "color": "#rrggbb"}, ...]}
/// listing every object (seen or not). Both files are written atomically.
Status write_object_ids(const ObjectIdImage& ids, const std::vector<std::string>& objects,
                        const std::filesystem::path& png);

}  // namespace roomcad
