// SPDX-License-Identifier: GPL-3.0-or-later
#include "testing/random_plan.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>

namespace roomcad::samples {
namespace {

/// SplitMix64: tiny, and the same sequence everywhere (std:: distributions are not).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(next() % n); }
  bool chance(int percent) { return below(100) < static_cast<std::size_t>(percent); }
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(next() >> 11) * 0x1.0p-53);
  }

 private:
  std::uint64_t state_;
};

class Generator {
 public:
  Generator(std::uint64_t seed, const RandomPlanOptions& options) : rng_(seed), options_(options) {}

  Plan plan() {
    Plan p;
    p.site.origin = point();
    p.site.cells = {static_cast<std::int64_t>(1 + rng_.below(200)),
                    static_cast<std::int64_t>(1 + rng_.below(200))};
    p.site.cell_size = number(0.1, 2.0);
    p.site.max_height = number(2.0, 20.0);
    p.site.tolerance = rng_.chance(50) ? 1e-6 : number(0.0, 0.01);
    p.site.floor_color = color();
    extras(p.site.extra);
    for (std::size_t i = rng_.below(options_.max_walls + 1); i > 0; --i) p.walls.push_back(wall());
    for (std::size_t i = rng_.below(options_.max_openings + 1); i > 0; --i)
      p.openings.push_back(opening(p));
    for (std::size_t i = rng_.below(options_.max_lights + 1); i > 0; --i)
      p.lights.push_back(light());
    for (std::size_t i = rng_.below(options_.max_cameras + 1); i > 0; --i)
      p.cameras.push_back(camera());
    extras(p.extra);
    return p;
  }

 private:
  /// Mostly plan-like decimals (a few digits), sometimes awkward doubles.
  double number(double lo, double hi) {
    if (options_.awkward_numbers && rng_.chance(15)) {
      switch (rng_.below(8)) {
        case 0: return -0.0;
        case 1: return 0.0;
        case 2:
          return std::numeric_limits<double>::denorm_min() *
                 static_cast<double>(1 + rng_.below(1000));
        case 3:
          return std::numeric_limits<double>::max() / static_cast<double>(1 + rng_.below(1000));
        case 4:
          return 1e15 + static_cast<double>(rng_.below(1000));  // where integers stop being plain
        case 5: return std::ldexp(rng_.uniform(-1, 1), static_cast<int>(rng_.below(200)) - 100);
        case 6: return 1.0 / 3.0 * static_cast<double>(1 + rng_.below(9));
        default: {
          double x;
          do x = std::bit_cast<double>(rng_.next());
          while (!std::isfinite(x));
          return x;
        }
      }
    }
    const double scale[] = {1, 10, 100, 1000, 10000};
    const double s = scale[rng_.below(5)];
    return std::round(rng_.uniform(lo, hi) * s) / s;
  }
  Point2 point() { return {number(-50, 50), number(-50, 50)}; }
  Vec3 vec() { return {number(-50, 50), number(-50, 50), number(-50, 50)}; }
  Color color() {
    const std::uint64_t bits = rng_.next();
    return {static_cast<std::uint8_t>(bits), static_cast<std::uint8_t>(bits >> 8),
            static_cast<std::uint8_t>(bits >> 16)};
  }

  std::string id(std::string_view prefix) {
    std::string s = std::string(prefix) + std::to_string(counter_++);
    if (options_.awkward_strings && rng_.chance(25)) {
      static const char* const kPieces[] = {"\"",   "\\",   "/", "~",    "~1", "\n", "\t",
                                            "\x01", "\x1f", "é", "日本", "😀",  " ",  "\x7f"};
      s += kPieces[rng_.below(std::size(kPieces))];
    }
    return s;
  }

  /// Canonical JSON values, as append_canonical writes them.
  std::string json_value(int depth) {
    switch (rng_.below(depth > 2 ? 5 : 7)) {
      case 0: return "null";
      case 1: return rng_.chance(50) ? "true" : "false";
      case 2: return std::to_string(static_cast<std::int64_t>(rng_.next() % 2001) - 1000);
      case 3: return rng_.chance(50) ? "0.5" : "-2.25";
      case 4: return "\"s" + std::to_string(rng_.below(100)) + "\"";
      case 5: {
        std::string s = "[";
        for (std::size_t i = rng_.below(4); i > 0; --i)
          s += (s.size() > 1 ? ", " : "") + json_value(depth + 1);
        return s + "]";
      }
      default: {
        std::string s = "{";
        const std::size_t n = rng_.below(4);
        for (std::size_t i = 0; i < n; ++i)  // keys k0 < k1 < ... are already sorted
          s += (i ? ", " : "") + ("\"k" + std::to_string(i) + "\": ") + json_value(depth + 1);
        return s + "}";
      }
    }
  }
  void extras(ExtraFields& extra) {
    if (!options_.extras || !rng_.chance(30)) return;
    for (std::size_t i = 1 + rng_.below(3); i > 0; --i)
      extra.push_back({"x_" + std::to_string(counter_++), json_value(0)});
    // Sorted by key, as the canonical writer orders them and the reader reads them back.
    std::sort(extra.begin(), extra.end(),
              [](const ExtraField& a, const ExtraField& b) { return a.key < b.key; });
  }

  Wall wall() {
    Wall w;
    w.id = id("w");
    w.from = point();
    w.to = point();
    w.thickness = number(0.05, 0.5);
    w.height = number(2.0, 4.0);
    w.base = rng_.chance(80) ? 0.0 : number(0.0, 3.0);
    w.color = color();
    extras(w.extra);
    return w;
  }
  Opening opening(const Plan& p) {
    Opening o;
    o.id = id("o");
    o.type = rng_.chance(50) ? OpeningType::door : OpeningType::window;
    o.wall =
        p.walls.empty() || rng_.chance(10) ? id("missing") : p.walls[rng_.below(p.walls.size())].id;
    o.offset = number(0.0, 10.0);
    o.width = number(0.5, 2.0);
    o.height = number(0.5, 2.5);
    o.sill = number(0.0, 1.5);
    o.hinge = rng_.chance(50) ? Hinge::left : Hinge::right;
    o.swing = rng_.chance(50) ? Swing::in : Swing::out;
    extras(o.extra);
    return o;
  }
  Light light() {
    Light l;
    l.id = id("l");
    l.direction = vec();
    l.intensity = number(0.0, 2.0);
    l.ambient = number(0.0, 1.0);
    extras(l.extra);
    return l;
  }
  Camera camera() {
    Camera c;
    c.id = id("c");
    c.projection = rng_.chance(50) ? Projection::perspective : Projection::orthographic;
    c.eye = vec();
    c.target = vec();
    c.up = rng_.chance(70) ? Vec3{0, 0, 1} : vec();
    c.fov_deg = number(10.0, 120.0);
    c.view_height = number(1.0, 50.0);
    extras(c.extra);
    return c;
  }

  Rng rng_;
  RandomPlanOptions options_;
  std::size_t counter_ = 0;
};

}  // namespace

Plan random_plan(std::uint64_t seed, const RandomPlanOptions& options) {
  return Generator(seed, options).plan();
}

}  // namespace roomcad::samples
