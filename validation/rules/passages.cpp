// SPDX-License-Identifier: GPL-3.0-or-later
// passage_too_narrow: the narrowest clear width between walls on the way between a room's
// doors.
//
// People walk between wall pieces: footprints cut at their door holes. Where two pieces of
// different walls are closer than the passage width, a person of that width cannot pass
// between them: the segment between their closest points is a barrier (every point of it is
// nearer than half the width to one of the two). Inside a room, the barriers and the pieces
// they join split the floor; the room's doors, in order along its outline, cut its boundary
// into arcs, and two doors are cut off from each other exactly when a chain of barriers and
// pieces joins an arc on one side of them to an arc on the other. A finding names each
// barrier that lies on such a chain: widening it (or the other barriers of its chain) opens
// the way. Whether two pieces are closer than the width is exact (squared distances, written
// numbers); which room and which arc a barrier belongs to is read from find_rooms' outline,
// whose corners are within 1e-15 (relative) of the true ones. Rooms with one door are left
// to door_clearance.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "validation/detail/diagnostics.h"
#include "validation/rules/door_geometry.h"
#include "validation/rules/passage_geometry.h"
#include "validation/rules/rules.h"

namespace roomcad::rules {
namespace {

/// Union-find over the nodes of one room: its arcs, then the free-standing pieces in it.
struct Nodes {
  std::vector<std::size_t> parent;
  std::size_t find(std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
};

/// The nodes a barrier joins: an arc of the room (by where its end touches the outline) or
/// the piece itself (inside the room).
struct Link {
  std::size_t barrier;
  std::size_t a;
  std::size_t b;
};

/// @return the arc of the room's boundary a parameter falls in: arcs run from door k to k+1.
std::size_t arc_of(const std::vector<double>& door_params, double t) {
  const auto it = std::upper_bound(door_params.begin(), door_params.end(), t);
  const std::size_t k = static_cast<std::size_t>(it - door_params.begin());
  return k == 0 ? door_params.size() - 1 : k - 1;
}

/// @return the arcs a node reaches without the link `skip`.
std::vector<bool> arcs_reached(std::size_t from, std::size_t arcs, std::size_t nodes,
                               const std::vector<Link>& links, std::size_t skip) {
  std::vector<bool> seen(nodes, false);
  std::vector<std::size_t> stack{from};
  seen[from] = true;
  while (!stack.empty()) {
    const std::size_t x = stack.back();
    stack.pop_back();
    for (std::size_t l = 0; l < links.size(); ++l) {
      if (l == skip) continue;
      const std::size_t y = links[l].a == x ? links[l].b : links[l].b == x ? links[l].a : nodes;
      if (y < nodes && !seen[y]) seen[y] = true, stack.push_back(y);
    }
  }
  seen.resize(arcs);
  return seen;
}

/// @return the links that lie on a chain between two different arcs.
std::vector<std::size_t> separating_links(std::size_t arcs, std::size_t nodes,
                                          const std::vector<Link>& links) {
  std::vector<std::size_t> out;
  for (std::size_t l = 0; l < links.size(); ++l) {
    if (links[l].a == links[l].b) continue;
    const std::vector<bool> ra = arcs_reached(links[l].a, arcs, nodes, links, l);
    const std::vector<bool> rb = arcs_reached(links[l].b, arcs, nodes, links, l);
    const auto count = [](const std::vector<bool>& v) {
      return std::count(v.begin(), v.end(), true);
    };
    bool apart = false;
    for (std::size_t i = 0; i < arcs && !apart; ++i)
      apart = ra[i] && (count(rb) > 1 || (count(rb) == 1 && !rb[i]));
    if (apart) out.push_back(l);
  }
  return out;
}

struct RoomPassages {
  const Context& cx;
  const Scene& scene;
  const Storey& storey;
  const PassageGeometry& geometry;
  Report& report;

  /// The room's doors by where they meet its outline.
  std::pair<std::vector<double>, std::vector<std::string>> doors_along(
      std::size_t r, const Outline& outline) const {
    std::vector<std::pair<double, std::string>> doors;
    for (std::size_t d = 0; d < storey.doors.size(); ++d)
      for (int side = 0; side < 2; ++side)
        if (storey.door_rooms[d][side] == r) {
          const Opening& o = scene.plan().openings[storey.doors[d]];
          doors.emplace_back(outline.param(door_face_middle(
                                 scene.plan().walls[*scene.host(storey.doors[d])], o, side)),
                             o.id);
        }
    std::sort(doors.begin(), doors.end());
    std::vector<double> params;
    std::vector<std::string> ids;
    for (auto& [t, id] : doors) params.push_back(t), ids.push_back(std::move(id));
    return {params, ids};
  }

  void check(std::size_t r, const std::vector<std::size_t>& barriers) const {
    const Room& room = storey.rooms[r];
    const Outline outline(room.outline);
    const auto [params, door_ids] = doors_along(r, outline);
    if (params.size() < 2) return;
    std::vector<Link> links;
    std::map<std::size_t, std::size_t> inner;  // piece -> node
    // A piece of a wall that bounds the room joins the arc its barrier end touches; any other
    // piece (a free-standing wall in the room) is a node of its own.
    const auto& door_params = params;  // a lambda may not capture a structured binding (clang 14)
    const auto node_of = [&](std::size_t piece, Point2 end) {
      const std::string& wall = scene.plan().walls[geometry.piece(piece).wall].id;
      if (std::binary_search(room.walls.begin(), room.walls.end(), wall))
        return arc_of(door_params, outline.param(end));
      return inner.emplace(piece, door_params.size() + inner.size()).first->second;
    };
    for (const std::size_t b : barriers) {
      const Barrier& bar = geometry.barrier(b);
      links.push_back({b, node_of(bar.p, bar.a), node_of(bar.q, bar.b)});
    }
    std::map<std::pair<std::string, std::string>, const Barrier*> narrowest;
    for (const std::size_t l :
         separating_links(params.size(), params.size() + inner.size(), links)) {
      const Barrier& bar = geometry.barrier(links[l].barrier);
      auto ids = std::minmax(scene.plan().walls[geometry.piece(bar.p).wall].id,
                             scene.plan().walls[geometry.piece(bar.q).wall].id);
      const Barrier*& slot = narrowest[{ids.first, ids.second}];
      if (!slot || bar.gap < slot->gap) slot = &bar;
    }
    for (const auto& [ids, bar] : narrowest) report_barrier(r, *bar, ids, door_ids);
  }

  void report_barrier(std::size_t r, const Barrier& bar,
                      const std::pair<std::string, std::string>& ids,
                      const std::vector<std::string>& doors) const {
    const double width = cx.rules.thresholds.passage_min_width;
    const std::optional<PassageFix> fix = geometry.find_fix(bar, width);
    report.add(make_finding(
        cx, Code::passage_too_narrow, {ids.first, ids.second},
        fmt::format("in {} the clear width between wall '{}' and wall '{}' is {}, narrower than "
                    "{}, on the only "
                    "way between the room's doors ({}).",
                    cx.room_name(storey, r), ids.first, ids.second, detail::metres(bar.gap),
                    detail::metres(width), fmt::join(doors, ", ")),
        fix ? fix->text
            : fmt::format("widen the gap between wall '{}' and wall '{}' to {}", ids.first,
                          ids.second, detail::metres(width)),
        fix ? fix->edits : std::vector<FixEdit>{},
        detail::box_where(std::min(bar.a.x, bar.b.x), std::min(bar.a.y, bar.b.y),
                          std::max(bar.a.x, bar.b.x), std::max(bar.a.y, bar.b.y))));
  }
};

}  // namespace

void check_passages(const Context& cx, const Scene& scene, Report& report) {
  if (!cx.rules.is_enabled(Code::passage_too_narrow)) return;
  for (const Storey& s : cx.storeys) {
    const PassageGeometry geometry(scene, s, cx.rules.thresholds.passage_min_width);
    std::vector<std::vector<std::size_t>> by_room(s.rooms.size());
    for (std::size_t b = 0; b < geometry.barrier_count(); ++b)
      by_room[geometry.barrier(b).room].push_back(b);
    const RoomPassages passages{cx, scene, s, geometry, report};
    for (std::size_t r = 0; r < s.rooms.size(); ++r)
      if (s.accessible[r] && !by_room[r].empty()) passages.check(r, by_room[r]);
  }
}

}  // namespace roomcad::rules
