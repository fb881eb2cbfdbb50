// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/frame_overlay.h"

#include <algorithm>

#include <fmt/format.h>

#include "view/text.h"

namespace roomcad {
namespace {

constexpr int kMargin = 4;
constexpr TextColor kWhite{0xff, 0xff, 0xff};
constexpr TextColor kYellow{0xff, 0xdc, 0x50};
constexpr TextColor kBlue{0x9c, 0xc8, 0xff};
constexpr TextColor kRed{0xff, 0x60, 0x60};
constexpr TextColor kGrey{0xd0, 0xd0, 0xd0};

struct Line {
  std::string text;
  TextColor color;
};

/// The panel's lines, cut to the frame's width.
std::vector<Line> panel_lines(const OverlayText& t, std::size_t max_chars) {
  std::vector<Line> lines;
  auto add = [&](const std::string& text, TextColor color) {
    lines.push_back({text.substr(0, max_chars), color});
  };
  for (const std::string& s : t.status) add(s, kWhite);
  if (!t.message.empty()) add(t.message, kYellow);
  for (const std::string& s : t.selection) add(s, kBlue);
  for (std::size_t i = 0; i < t.errors.size() && i < kMaxErrorLines; ++i) add(t.errors[i], kRed);
  if (t.errors.size() > kMaxErrorLines)
    add(fmt::format("... and {} more errors", t.errors.size() - kMaxErrorLines), kRed);
  return lines;
}

}  // namespace

void draw_overlay(RgbImage& image, const OverlayText& text) {
  const int line = text_line_height() + 1;
  const std::size_t max_chars =
      static_cast<std::size_t>(std::max(0, (image.width - 2 * kMargin) / text_width(" ")));
  const std::vector<Line> lines = panel_lines(text, max_chars);
  int widest = 0;
  for (const Line& l : lines) widest = std::max(widest, text_width(l.text));
  darken_rect(image, 0, 0, widest + 2 * kMargin,
              static_cast<int>(lines.size()) * line + 2 * kMargin);
  for (std::size_t i = 0; i < lines.size(); ++i)
    draw_text(image, kMargin, kMargin + static_cast<int>(i) * line, lines[i].text, lines[i].color);
  if (text.help.empty()) return;
  const std::string help = text.help.substr(0, max_chars);
  const int top = image.height - line - kMargin;
  darken_rect(image, 0, top - kMargin, text_width(help) + 2 * kMargin, line + 2 * kMargin);
  draw_text(image, kMargin, top, help, kGrey);
}

}  // namespace roomcad
