#include "view/object_properties.h"

#include <algorithm>

#include <fmt/format.h>

namespace roomcad {
namespace {

template <class T>
const T* find_by_id(const std::vector<T>& items, std::string_view id) {
  const auto it = std::find_if(items.begin(), items.end(), [&](const T& t) { return t.id == id; });
  return it == items.end() ? nullptr : &*it;
}

std::string point(const Point2& p) { return fmt::format("{}, {}", p.x, p.y); }
std::string point(const Vec3& p) { return fmt::format("{}, {}, {}", p.x, p.y, p.z); }

std::vector<std::string> describe(const Wall& w) {
  return {fmt::format("wall {}", w.id), fmt::format("from {}  to {} m", point(w.from), point(w.to)),
          fmt::format("thickness {} m  height {} m  base {} m", w.thickness, w.height, w.base),
          fmt::format("color {}", to_string(w.color))};
}

std::vector<std::string> describe(const Opening& o) {
  return {fmt::format("{} {} in wall {}", to_string(o.type), o.id, o.wall),
          fmt::format("offset {} m  width {} m  height {} m  sill {} m", o.offset, o.width,
                      o.height, o.sill),
          fmt::format("hinge {}  swing {}", to_string(o.hinge), to_string(o.swing))};
}

std::vector<std::string> describe(const Light& l) {
  return {fmt::format("light {}", l.id), fmt::format("direction {}", point(l.direction)),
          fmt::format("intensity {}  ambient {}", l.intensity, l.ambient)};
}

std::vector<std::string> describe(const Camera& c) {
  return {fmt::format("camera {} ({})", c.id, to_string(c.projection)),
          fmt::format("eye {}  target {} m", point(c.eye), point(c.target)),
          fmt::format("fov {} deg  view height {} m", c.fov_deg, c.view_height)};
}

}  // namespace

std::vector<std::string> describe_object(const Plan& plan, std::string_view id) {
  if (const Wall* w = find_by_id(plan.walls, id)) return describe(*w);
  if (const Opening* o = find_by_id(plan.openings, id)) return describe(*o);
  if (const Light* l = find_by_id(plan.lights, id)) return describe(*l);
  if (const Camera* c = find_by_id(plan.cameras, id)) return describe(*c);
  return {};
}

}  // namespace roomcad
