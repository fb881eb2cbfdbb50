// SPDX-License-Identifier: GPL-3.0-or-later
// A built-in bitmap font, so the window can write text without a font library.
#pragma once

#include <array>
#include <cstdint>

namespace roomcad::detail {

inline constexpr int kGlyphWidth = 6;
inline constexpr int kGlyphHeight = 13;
inline constexpr int kFirstGlyph = 32;  ///< ' '
inline constexpr int kGlyphCount = 95;  ///< ' ' .. '~'

/// Rows of one glyph, top first; bit 7 is the leftmost of its kGlyphWidth pixels.
using Glyph = std::array<std::uint8_t, kGlyphHeight>;

extern const std::array<Glyph, kGlyphCount> kFont6x13;

}  // namespace roomcad::detail
