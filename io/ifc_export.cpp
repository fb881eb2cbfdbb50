// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/ifc_export.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

#include "geometry/rooms.h"
#include "io/atomic_write.h"
#include "io/detail/ifc_shapes.h"
#include "io/ifc_guid.h"
#include "io/step_file.h"
#include "plan/plan_chords.h"
#include "plan/plan_levels.h"
#include "plan/plan_objects.h"

namespace roomcad {
namespace {

using io_detail::IfcShapeWriter;
using step::ref;

/// @return the quoted IFC GlobalId of `key` (io/ifc_guid.h).
std::string global_id(std::string_view key) {
  std::string quoted = "'";  // appended, not `'\'' + ...`: GCC 12 warns (-Wrestrict) on that
  quoted += ifc_global_id(key);
  quoted += '\'';
  return quoted;
}

std::string text(std::string_view s) {
  std::string out;
  step::append_string(out, s);
  return out;
}

std::string real(double x) {
  std::string out;
  step::append_real(out, x);
  return out;
}

std::string refs(const std::vector<int>& ids) {
  std::string out = "(";
  for (const int id : ids) {
    if (out.size() > 1) out += ',';
    out += ref(id);  // appended, not `"," + ...`: GCC 12 warns (-Wrestrict) on that
  }
  return out + ')';
}

/// The head every IfcRoot shares: GlobalId, OwnerHistory (none), Name, Description.
std::string root(std::string_view kind, std::string_view id, std::string_view name) {
  return global_id(std::string(kind) + ':' + std::string(id)) + ",$," + text(name) + ",$";
}

struct Storey {
  std::string level;  ///< level id; empty: the objects of no level
  std::string name;
  double elevation = 0.0;
  double height = 2.8;
  int placement = 0;
  int entity = 0;
  std::vector<int> elements{};
  std::vector<int> spaces{};
};

class IfcBuilder {
 public:
  IfcBuilder(const Plan& plan, IfcExportSummary& summary)
      : plan_(plan),
        chorded_(with_arcs_as_chords(with_absolute_heights(plan))),
        joins_(find_joins(chorded_.plan)),
        joined_(chorded_.plan, joins_),
        openings_of_(openings_by_wall(plan_)),
        summary_(summary) {
    // Each wall's chords (one for a straight wall) and each opening's pieces, in order.
    chords_.resize(plan_.walls.size());
    for (std::size_t j = 0; j < chorded_.source_wall.size(); ++j)
      chords_[chorded_.source_wall[j]].push_back(j);
    pieces_.resize(plan_.openings.size());
    for (std::size_t p = 0; p < chorded_.source_opening.size(); ++p)
      pieces_[chorded_.source_opening[p]].push_back(p);
  }

  std::string build(std::string_view name) {
    const int project = write_context(name);
    const int site_placement = w_.add("IFCLOCALPLACEMENT", "$," + ref(world_));
    const int site = w_.add("IFCSITE", root("site", "", "Site") + ",$," + ref(site_placement) +
                                           ",$,$,.ELEMENT.,$,$,$,$,$");
    const int building_placement =
        w_.add("IFCLOCALPLACEMENT", ref(site_placement) + ',' + ref(world_));
    const int building =
        w_.add("IFCBUILDING", root("building", "", "Building") + ",$," + ref(building_placement) +
                                  ",$,$,.ELEMENT.,$,$,$");
    w_.add("IFCRELAGGREGATES",
           root("aggregates", "project", "") + ',' + ref(project) + ",(" + ref(site) + ')');
    w_.add("IFCRELAGGREGATES",
           root("aggregates", "site", "") + ',' + ref(site) + ",(" + ref(building) + ')');
    write_storeys(building_placement);
    for (std::size_t i = 0; i < plan_.walls.size(); ++i) write_wall(i);
    for (const Slab& slab : plan_.slabs) write_slab(slab);
    for (Storey& storey : storeys_) write_spaces(storey);
    std::vector<int> storey_entities;
    for (const Storey& storey : storeys_) {
      storey_entities.push_back(storey.entity);
      if (!storey.elements.empty())
        w_.add("IFCRELCONTAINEDINSPATIALSTRUCTURE", root("contains", storey.level, "") + ',' +
                                                        refs(storey.elements) + ',' +
                                                        ref(storey.entity));
      if (!storey.spaces.empty())
        w_.add("IFCRELAGGREGATES", root("aggregates-spaces", storey.level, "") + ',' +
                                       ref(storey.entity) + ',' + refs(storey.spaces));
    }
    w_.add("IFCRELAGGREGATES",
           root("aggregates", "building", "") + ',' + ref(building) + ',' + refs(storey_entities));
    summary_.storeys = storeys_.size();
    return w_.finish(name, "IFC4", "ViewDefinition [ReferenceView_V1.2]");
  }

 private:
  const Plan& plan_;
  const ChordPlan chorded_;  ///< heights absolute, arc walls as their chords
  const Joins joins_;        ///< of chorded_.plan
  const io_detail::JoinedWalls joined_;
  std::vector<std::vector<std::size_t>> chords_;  ///< per wall, its walls in chorded_
  std::vector<std::vector<std::size_t>> pieces_;  ///< per opening, its openings in chorded_
  const OpeningsByWall openings_of_;              ///< per wall, its openings
  IfcExportSummary& summary_;
  step::Writer w_;
  IfcShapeWriter shapes_{w_};
  int world_ = 0;
  std::vector<Storey> storeys_;
  std::unordered_map<std::string, std::size_t> storey_of_level_;

  /// Units, the representation contexts and the project. @return the IfcProject.
  int write_context(std::string_view name) {
    const int origin = w_.add("IFCCARTESIANPOINT", "(0.,0.,0.)");
    shapes_.up = w_.add("IFCDIRECTION", "(0.,0.,1.)");
    const int east = w_.add("IFCDIRECTION", "(1.,0.,0.)");
    world_ = w_.add("IFCAXIS2PLACEMENT3D", ref(origin) + ',' + ref(shapes_.up) + ',' + ref(east));
    const int context =
        w_.add("IFCGEOMETRICREPRESENTATIONCONTEXT", "$,'Model',3,1.E-06," + ref(world_) + ",$");
    shapes_.body_context = w_.add("IFCGEOMETRICREPRESENTATIONSUBCONTEXT",
                                  "'Body','Model',*,*,*,*," + ref(context) + ",$,.MODEL_VIEW.,$");
    shapes_.axis_context = w_.add("IFCGEOMETRICREPRESENTATIONSUBCONTEXT",
                                  "'Axis','Model',*,*,*,*," + ref(context) + ",$,.GRAPH_VIEW.,$");
    std::vector<int> units;
    for (const char* unit : {".LENGTHUNIT.,$,.METRE.", ".AREAUNIT.,$,.SQUARE_METRE.",
                             ".VOLUMEUNIT.,$,.CUBIC_METRE.", ".PLANEANGLEUNIT.,$,.RADIAN."})
      units.push_back(w_.add("IFCSIUNIT", std::string("*,") + unit));
    const int assignment = w_.add("IFCUNITASSIGNMENT", refs(units));
    return w_.add("IFCPROJECT",
                  root("project", "", name) + ",$,$,$,(" + ref(context) + ")," + ref(assignment));
  }

  void write_storeys(int building_placement) {
    const bool levelless = plan_.levels.empty() ||
                           std::any_of(plan_.walls.begin(), plan_.walls.end(),
                                       [](const Wall& w) { return w.level.empty(); }) ||
                           std::any_of(plan_.slabs.begin(), plan_.slabs.end(),
                                       [](const Slab& s) { return s.level.empty(); });
    if (levelless) {
      double height = 0.0;
      for (const Wall& wall : plan_.walls)
        if (wall.level.empty())
          height = std::max({height, wall.height, wall.height_at_end.value_or(0.0)});
      storeys_.push_back({.level = "", .name = "ground", .height = height > 0.0 ? height : 2.8});
    }
    for (const Level& level : plan_.levels) {
      storey_of_level_.emplace(level.id, storeys_.size());
      storeys_.push_back({.level = level.id,
                          .name = level.id,
                          .elevation = level.elevation,
                          .height = level.height});
    }
    for (Storey& s : storeys_) {
      const int at =
          w_.add("IFCAXIS2PLACEMENT3D", ref(shapes_.point({0.0, 0.0}, s.elevation)) + ",$,$");
      s.placement = w_.add("IFCLOCALPLACEMENT", ref(building_placement) + ',' + ref(at));
      s.entity =
          w_.add("IFCBUILDINGSTOREY", root("storey", s.level, s.name) + ",$," + ref(s.placement) +
                                          ",$,$,.ELEMENT.," + real(s.elevation));
    }
  }

  Storey& storey_of(const std::string& level) {
    const auto it = storey_of_level_.find(level);
    return storeys_[it == storey_of_level_.end() ? 0 : it->second];
  }

  /// @return an IFCLOCALPLACEMENT relative to `parent`, at height z (metres), axes unchanged.
  int local_placement(int parent, double z) {
    const int at = w_.add("IFCAXIS2PLACEMENT3D", ref(shapes_.point({0.0, 0.0}, z)) + ",$,$");
    return w_.add("IFCLOCALPLACEMENT", ref(parent) + ',' + ref(at));
  }

  void write_wall(std::size_t i) {
    const Wall& wall = plan_.walls[i];
    Storey& storey = storey_of(wall.level);
    const int placement = local_placement(storey.placement, wall.base);
    // One body item per chord: its footprint after its joins, extruded (or, sloped, a face set).
    std::vector<int> items;
    std::vector<Point2> axis{wall.from};
    for (const std::size_t j : chords_[i]) {
      const Wall& chord = chorded_.plan.walls[j];
      items.push_back(
          io_detail::wall_body(shapes_, chord, io_detail::export_footprint(joined_, j)));
      axis.push_back(chord.to);
    }
    const int shape = shapes_.product_shape(wall.height_at_end ? "Tessellation" : "SweptSolid",
                                            items, io_detail::wall_axis(shapes_, axis));
    const int entity =
        w_.add("IFCWALL", root("wall", wall.id, wall.id) + ",$," + ref(placement) + ',' +
                              ref(shape) + ',' + text(wall.id) + ",.STANDARD.");
    storey.elements.push_back(entity);
    ++summary_.walls;
    for (const std::size_t o : openings_of_[i]) write_opening(o, i, entity, placement, storey);
  }

  /// The void of an opening in a straight wall: its outline (its shape if it has one) in the
  /// wall's vertical plane, extruded through the wall.
  int straight_void(const Opening& o, const Wall& wall) {
    const double length = std::hypot(wall.to.x - wall.from.x, wall.to.y - wall.from.y);
    const Point2 d{(wall.to.x - wall.from.x) / length, (wall.to.y - wall.from.y) / length};
    // The profile lies in the wall's vertical plane (x along the wall, y up) one thickness on
    // its left; it is extruded two thicknesses to the right, through the whole wall.
    const Point2 start{wall.from.x + o.offset * d.x - wall.thickness * d.y,
                       wall.from.y + o.offset * d.y + wall.thickness * d.x};
    const int position = shapes_.placement(start, o.sill, {d.y, -d.x, 0.0}, {d.x, d.y, 0.0});
    std::vector<Point2> outline{{0.0, 0.0}, {o.width, 0.0}, {o.width, o.height}, {0.0, o.height}};
    if (!o.shape.empty()) {
      outline.clear();
      for (const Point2& p : o.shape) outline.push_back({p.x * o.width, p.y * o.height});
    }
    return shapes_.extrusion(outline, {}, position, 2.0 * wall.thickness, wall.color);
  }

  /// The void items of opening `o` in arc wall `wall`: one per chord its span crosses.
  std::vector<int> arc_voids(std::size_t o, std::size_t wall) {
    std::vector<int> items;
    const std::vector<std::size_t>& chords = chords_[wall];
    for (const std::size_t p : pieces_[o]) {
      const std::size_t j = chorded_.chord[p];
      const Opening& piece = chorded_.plan.openings[p];
      const Wall& chord = chorded_.plan.walls[j];
      const double length = std::hypot(chord.to.x - chord.from.x, chord.to.y - chord.from.y);
      // On into the neighbouring chord: from its start, or to its end (within the rounding of
      // the offsets along the polyline), as the build's pieces meet on the mitre plane.
      const bool first = j == chords.front(), last = j == chords.back();
      const std::array<bool, 2> mitred{
          !first && piece.offset == 0.0,
          !last && piece.offset + piece.width >= length * (1.0 - 1e-12)};
      items.push_back(io_detail::chord_piece_void(
          shapes_, chord, io_detail::export_footprint(joined_, j), piece, mitred));
    }
    return items;
  }

  void write_opening(std::size_t index, std::size_t w, int wall_entity, int wall_placement,
                     Storey& storey) {
    const Opening& o = plan_.openings[index];
    const Wall& wall = plan_.walls[w];
    std::vector<int> body;
    if (chords_[w].size() > 1) body = arc_voids(index, w);
    if (body.empty()) body.push_back(straight_void(o, wall));  // straight, or (invalid) off its arc
    const int placement = local_placement(wall_placement, 0.0);
    const int element =
        w_.add("IFCOPENINGELEMENT", root("opening", o.id, o.id) + ",$," + ref(placement) + ',' +
                                        ref(shapes_.product_shape("SweptSolid", body)) + ',' +
                                        text(o.id) + ",.OPENING.");
    w_.add("IFCRELVOIDSELEMENT",
           root("voids", o.id, "") + ',' + ref(wall_entity) + ',' + ref(element));
    const std::string sizes = real(o.height) + ',' + real(o.width);
    const std::string head = ",$," + local_ref(placement) + ",$," + text(o.id) + ',' + sizes;
    const bool door = o.type == OpeningType::door;
    const int filling =
        door
            ? w_.add("IFCDOOR",
                     root("door", o.id, o.id) + head + ",.DOOR.," +
                         (o.hinge == Hinge::left ? ".SINGLE_SWING_LEFT." : ".SINGLE_SWING_RIGHT.") +
                         ",$")
            : w_.add("IFCWINDOW", root("window", o.id, o.id) + head + ",.WINDOW.,.SINGLE_PANEL.,$");
    w_.add("IFCRELFILLSELEMENT", root("fills", o.id, "") + ',' + ref(element) + ',' + ref(filling));
    storey.elements.push_back(filling);
    ++summary_.openings;
    ++(door ? summary_.doors : summary_.windows);
  }

  std::string local_ref(int parent) { return ref(local_placement(parent, 0.0)); }

  void write_slab(const Slab& slab) {
    Storey& storey = storey_of(slab.level);
    const int placement = local_placement(storey.placement, slab.top - slab.thickness);
    const int body = shapes_.extrusion(slab.outline, slab.holes, 0, slab.thickness, slab.color);
    const int entity =
        w_.add("IFCSLAB", root("slab", slab.id, slab.id) + ",$," + ref(placement) + ',' +
                              ref(shapes_.product_shape("SweptSolid", {body})) + ',' +
                              text(slab.id) + ",.FLOOR.");
    storey.elements.push_back(entity);
    ++summary_.slabs;
  }

  /// One IfcSpace per room of the storey's walls, with its NetFloorArea.
  void write_spaces(Storey& storey) {
    const std::vector<Room> rooms = find_rooms_on_level(plan_, storey.level);
    for (std::size_t r = 0; r < rooms.size(); ++r) {
      const std::string id =
          fmt::format("{}room-{}", storey.level.empty() ? "" : storey.level + ':', r + 1);
      const int placement = local_placement(storey.placement, 0.0);
      const int body =
          shapes_.extrusion(rooms[r].outline, {}, 0, storey.height, plan_.site.floor_color);
      const int space = w_.add("IFCSPACE", root("space", id, fmt::format("Room {}", r + 1)) +
                                               ",$," + ref(placement) + ',' +
                                               ref(shapes_.product_shape("SweptSolid", {body})) +
                                               ",$,.ELEMENT.,.INTERNAL.,$");
      const int area =
          w_.add("IFCQUANTITYAREA", "'NetFloorArea',$,$," + real(rooms[r].area) + ",$");
      const int quantities = w_.add("IFCELEMENTQUANTITY", root("quantities", id, "BaseQuantities") +
                                                              ",$,(" + ref(area) + ')');
      w_.add("IFCRELDEFINESBYPROPERTIES",
             root("defines", id, "") + ",(" + ref(space) + ")," + ref(quantities));
      storey.spaces.push_back(space);
      ++summary_.spaces;
    }
  }
};

}  // namespace

Result<std::string> format_ifc(const Plan& plan, std::string_view name, IfcExportSummary* summary) {
  // An arc wall's openings are cut chord by chord as rectangles; a shape would need its
  // outline bent around the arc.
  for (const Opening& o : plan.openings) {
    if (o.shape.empty()) continue;
    const auto wall = std::find_if(plan.walls.begin(), plan.walls.end(),
                                   [&](const Wall& w) { return w.id == o.wall; });
    if (wall != plan.walls.end() && wall->arc_extent)
      return Result<std::string>::failure(
          Code::unsupported,
          fmt::format("opening \"{}\" has a shape ({} corners) in arc wall \"{}\": IFC export "
                      "cuts only rectangles in arc walls",
                      o.id, o.shape.size(), wall->id));
  }
  IfcExportSummary counts;
  std::string out = IfcBuilder(plan, counts).build(name);
  if (summary) *summary = counts;
  return out;
}

Status write_ifc_file(const std::filesystem::path& path, const Plan& plan,
                      IfcExportSummary* summary) {
  const Result<std::string> text = format_ifc(plan, path.filename().string(), summary);
  if (!text)
    return Status::failure(text.error().code,
                           fmt::format("{}: {}", path.string(), text.error().message));
  return write_file_atomically(path, text.value());
}

}  // namespace roomcad
