// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/detail/habitable_rooms.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "validation/rules/context.h"

namespace roomcad::detail {
namespace {

/// The words of a name: runs of letters, digits and non-ASCII bytes, in lower case.
std::vector<std::string> words_of(std::string_view name) {
  std::vector<std::string> words(1);
  for (const char c : lower_case(name)) {
    const auto byte = static_cast<unsigned char>(c);
    if (std::isalnum(byte) || byte >= 0x80) {
      words.back() += c;
    } else if (!words.back().empty()) {
      words.emplace_back();
    }
  }
  if (words.back().empty()) words.pop_back();
  return words;
}

bool names_a_room_not_lived_in(std::string_view name, const std::vector<std::string>& words) {
  return std::any_of(words.begin(), words.end(), [&](const std::string& w) {
    const bool plural = w.size() > 1 && w.back() == 's';
    return w == name || (plural && std::string_view(w).substr(0, w.size() - 1) == name);
  });
}

/// Whether the outline is at most `width` across some side's direction, and three times as
/// long along it.
bool is_corridor(const std::vector<Point2>& outline, double width) {
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const Point2 a = outline[i], b = outline[(i + 1) % outline.size()];
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    if (length == 0.0) continue;
    const double ux = (b.x - a.x) / length, uy = (b.y - a.y) / length;
    double lo_u = INFINITY, hi_u = -INFINITY, lo_v = INFINITY, hi_v = -INFINITY;
    for (const Point2& p : outline) {
      const double u = p.x * ux + p.y * uy, v = p.y * ux - p.x * uy;
      lo_u = std::min(lo_u, u), hi_u = std::max(hi_u, u);
      lo_v = std::min(lo_v, v), hi_v = std::max(hi_v, v);
    }
    const double across = hi_v - lo_v, along = hi_u - lo_u;
    if (across <= width && along >= 3.0 * across) return true;
  }
  return false;
}

}  // namespace

std::string lower_case(std::string_view text) {
  std::string out(text);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

bool is_habitable(const Room& room, std::string_view name, const HabitableRooms& rules) {
  if (!name.empty()) {
    const std::vector<std::string> words = words_of(name);
    return std::none_of(rules.not_habitable.begin(), rules.not_habitable.end(),
                        [&](const std::string& n) { return names_a_room_not_lived_in(n, words); });
  }
  return room.area >= rules.min_area && !is_corridor(room.outline, rules.corridor_width);
}

}  // namespace roomcad::detail
