// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/rules/door_fixes.h"

#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "validation/rules/door_tests.h"
#include "validation/rules/fix_search.h"

namespace roomcad::rules {
namespace {

constexpr double kSlideStep = 0.05;  ///< metres between the places along a wall that are tried
constexpr int kMaxSlides = 400;      ///< 20 m each way

double wall_length(const Wall& w) { return std::hypot(w.to.x - w.from.x, w.to.y - w.from.y); }

Hinge other(Hinge h) { return h == Hinge::left ? Hinge::right : Hinge::left; }
Swing other(Swing s) { return s == Swing::in ? Swing::out : Swing::in; }

/// The door with its leaf turned every other way: hinge, swing, both.
std::vector<Opening> flips(const Opening& o) {
  std::vector<Opening> out(3, o);
  out[0].hinge = other(o.hinge);
  out[1].swing = other(o.swing);
  out[2].hinge = other(o.hinge), out[2].swing = other(o.swing);
  return out;
}

/// Every leaf setting of the door, its own first.
std::vector<Opening> settings(const Opening& o) {
  std::vector<Opening> out{o};
  for (const Opening& f : flips(o)) out.push_back(f);
  return out;
}

/// The door at places along its wall on a 5 cm grid, nearest first, in every leaf setting.
std::vector<Opening> slides(const Opening& o, double length) {
  std::vector<Opening> out;
  const long long start = std::llround(o.offset * 100);
  for (int k = 1; k <= kMaxSlides; ++k)
    for (const int sign : {1, -1}) {
      const double offset =
          static_cast<double>(start + sign * k * std::llround(kSlideStep * 100)) / 100;
      if (offset < 0 || offset + o.width > length) continue;
      for (Opening s : settings(o)) {
        s.offset = offset;
        out.push_back(s);
      }
    }
  return out;
}

std::string side_words(Swing s) {
  return s == Swing::in ? "in (to its wall's left side)" : "out (to its wall's right side)";
}

/// The change from `o` to `c` as edits and words.
DoorFix describe(const Opening& o, const Opening& c, const Wall& host) {
  std::vector<std::pair<std::string, std::string>> fields;
  std::vector<std::string> words;
  if (c.offset != o.offset) {
    fields.emplace_back("offset", number_text(c.offset));
    words.push_back(
        fmt::format("move it along wall '{}' to offset {}", host.id, number_text(c.offset)));
  }
  if (c.width != o.width) {
    fields.emplace_back("width", number_text(c.width));
    words.push_back(fmt::format("make it {} m wide", number_text(c.width)));
  }
  if (c.hinge != o.hinge) {
    fields.emplace_back("hinge", std::string(to_string(c.hinge)));
    words.push_back(fmt::format("hinge it on the {}", to_string(c.hinge)));
  }
  if (c.swing != o.swing) {
    fields.emplace_back("swing", std::string(to_string(c.swing)));
    words.push_back("swing it " + side_words(c.swing));
  }
  return {fmt::format("{}", fmt::join(words, ", ")), {set_edit(o.id, std::move(fields))}};
}

}  // namespace

const BoxGrid& DoorFixer::leaves() const {
  if (leaves_) return *leaves_;
  std::vector<Box2> boxes;
  for (std::size_t i = 0; i < scene_.plan().openings.size(); ++i) {
    const Opening& o = scene_.plan().openings[i];
    if (o.type != OpeningType::door || !scene_.host(i)) continue;
    Box2 b = leaf_box(scene_, o, *scene_.host(i));
    b.index = i;
    boxes.push_back(b);
  }
  return leaves_.emplace(std::move(boxes));
}

DoorFixer::Needs DoorFixer::all_needs(std::size_t door) const {
  return {cx_.rules.is_enabled(Code::door_swing_blocked),
          cx_.rules.is_enabled(Code::door_clearance) && cx_.accessible_door[door]};
}

bool DoorFixer::passes(std::size_t door, const Opening& c, Needs needs, Precision precision) const {
  const std::size_t host = *scene_.host(door);
  if (needs.clearance &&
      !walls_in_clearance(scene_, c, host, cx_.rules.thresholds, precision).empty())
    return false;
  if (!needs.swing) return true;
  if (!walls_hit_by_leaf(scene_, c, host, precision).empty()) return false;
  for (const std::size_t other : leaves().find(leaf_box(scene_, c, host)))
    if (other != door &&
        leaves_meet(scene_, c, host, scene_.plan().openings[other], *scene_.host(other), precision))
      return false;
  return true;
}

std::optional<DoorFix> DoorFixer::first_fix(std::size_t door,
                                            const std::vector<Opening>& candidates,
                                            Needs own) const {
  const Opening& o = scene_.plan().openings[door];
  const Wall& host = scene_.plan().walls[*scene_.host(door)];
  const Needs every = all_needs(door);
  std::optional<Neighbourhood> near;
  std::optional<DoorFix> fallback;
  const auto is_clean = [&](const DoorFix& fix) {
    if (!near) {
      const double reach = std::max(o.width, cx_.rules.thresholds.clearance_depth) + o.width;
      near.emplace(scene_, grown(scene_.wall_box(*scene_.host(door)), reach), heights_of(host));
    }
    return near->try_edits(fix.edits).has_value();
  };
  // Candidates are sorted out in doubles; the ones kept are verified exactly.
  const auto check = [&](const Opening& c, Needs needs) {
    return passes(door, c, needs, Precision::approximate) &&
           passes(door, c, needs, Precision::exact);
  };
  for (const Opening& c : candidates) {
    const bool strong = check(c, every);
    if (!strong && (fallback || !check(c, own))) continue;
    DoorFix fix = describe(o, c, host);
    if (!is_clean(fix)) continue;
    if (strong) return fix;
    fallback = std::move(fix);
  }
  return fallback;
}

std::optional<DoorFix> DoorFixer::find(std::size_t door, Code code) const {
  const Opening& o = scene_.plan().openings[door];
  std::vector<Opening> candidates = flips(o);
  const std::vector<Opening> moved =
      slides(o, wall_length(scene_.plan().walls[*scene_.host(door)]));
  candidates.insert(candidates.end(), moved.begin(), moved.end());
  Needs own;
  (code == Code::door_clearance ? own.clearance : own.swing) = true;
  return first_fix(door, candidates, own);
}

std::optional<DoorFix> DoorFixer::widen(std::size_t door) const {
  const Opening& o = scene_.plan().openings[door];
  const double width = centimetres_up(cx_.rules.thresholds.door_min_width);
  const double grow = width - o.width;
  std::vector<Opening> candidates;
  for (const double offset :
       {centimetres_down(o.offset - grow / 2), o.offset, centimetres_down(o.offset - grow)})
    for (Opening s : settings(o)) {
      s.offset = offset, s.width = width;
      if (offset >= 0) candidates.push_back(s);
    }
  return first_fix(door, candidates, Needs{});
}

}  // namespace roomcad::rules
