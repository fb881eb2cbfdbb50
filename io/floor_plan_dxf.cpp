// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/floor_plan_dxf.h"

#include <charconv>
#include <cmath>
#include <numbers>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "io/atomic_write.h"

namespace roomcad {
namespace {

/// Writes group codes and values, numbering handles in writing order.
class DxfWriter {
 public:
  void group(int code, std::string_view value) {
    out_ += fmt::format("{:>3}\n", code);
    out_ += value;
    out_ += '\n';
  }
  void group(int code, double value) {
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value + 0.0).ptr;
    group(code, std::string_view(buffer, static_cast<std::size_t>(end - buffer)));
  }
  void group(int code, int value) { group(code, std::string_view(std::to_string(value))); }
  /// @return a new handle, written with group code `code` (5, or 105 for a DIMSTYLE).
  std::string handle(int code = 5) {
    const std::string h = fmt::format("{:X}", next_++);
    group(code, std::string_view(h));
    return h;
  }
  [[nodiscard]] int next_handle() const { return next_; }
  std::string& text() { return out_; }

 private:
  std::string out_;
  int next_ = 0x20;  // below: the fixed handles of the tables (see write_tables)
};

/// The plan point of a paper point.
struct ToPlan {
  double mm_per_m;
  Point2 origin;
  [[nodiscard]] Point2 operator()(Point2 p) const {
    return {(p.x - origin.x) / mm_per_m, (origin.y - p.y) / mm_per_m};
  }
};

constexpr const char* kModelSpace = "1F";  ///< the *Model_Space block record's handle

class PlanDxf {
 public:
  PlanDxf(DxfWriter& w, const FloorPlanDrawing& d) : w_(w), d_(d), to_plan_{d.mm_per_m, d.origin} {}

  void write_entities() {
    for (const PaperPolygon& p : d_.cut_walls) polyline("WALLS_CUT", p), hatch("WALLS_CUT", p);
    for (const PaperPolygon& p : d_.walls_below) polyline("WALLS_BELOW", p);
    for (const PaperPolygon& p : d_.walls_above) polyline("WALLS_ABOVE", p);
    for (const PaperLine& l : d_.windows) line("WINDOWS", l);
    for (const PaperLine& l : d_.door_leaves) line("DOORS", l);
    for (const PaperArc& a : d_.door_swings) arc("DOORS", a);
    for (const PaperLine& l : d_.dimension_lines) line("DIMENSIONS", l);
    for (const PaperText& t : d_.dimension_texts) text("DIMENSIONS", t);
    for (const PaperPolygon& p : d_.rooms) polyline("ROOMS", p);
    for (const PaperText& t : d_.room_labels) text("ROOMS", t);
  }

 private:
  DxfWriter& w_;
  const FloorPlanDrawing& d_;
  ToPlan to_plan_;

  void head(std::string_view type, std::string_view layer) {
    w_.group(0, type);
    w_.handle();
    w_.group(330, std::string_view(kModelSpace));
    w_.group(100, "AcDbEntity");
    w_.group(8, layer);
  }
  void point(int code, Point2 p) {
    w_.group(code, p.x);
    w_.group(code + 10, p.y);
  }
  void point3(int code, Point2 p) {
    point(code, p);
    w_.group(code + 20, 0.0);
  }

  void polyline(std::string_view layer, const PaperPolygon& polygon) {
    head("LWPOLYLINE", layer);
    w_.group(100, "AcDbPolyline");
    w_.group(90, static_cast<int>(polygon.size()));
    w_.group(70, 1);  // closed
    for (const Point2& p : polygon) point(10, to_plan_(p));
  }

  void hatch(std::string_view layer, const PaperPolygon& polygon) {
    head("HATCH", layer);
    w_.group(100, "AcDbHatch");
    point3(10, {0.0, 0.0});
    w_.group(210, 0.0), w_.group(220, 0.0), w_.group(230, 1.0);
    w_.group(2, "SOLID");
    w_.group(70, 1);  // solid fill
    w_.group(71, 0);  // not associative
    w_.group(91, 1);  // one boundary path,
    w_.group(92, 3);  // external, a polyline
    w_.group(72, 0);  // without bulges
    w_.group(73, 1);  // closed
    w_.group(93, static_cast<int>(polygon.size()));
    for (const Point2& p : polygon) point(10, to_plan_(p));
    w_.group(97, 0);
    w_.group(75, 1);  // hatch style: outer
    w_.group(76, 1);  // predefined pattern
    w_.group(98, 0);
  }

  void line(std::string_view layer, const PaperLine& l) {
    head("LINE", layer);
    w_.group(100, "AcDbLine");
    point3(10, to_plan_(l.a));
    point3(11, to_plan_(l.b));
  }

  /// DXF arcs turn counter-clockwise from the start angle; the paper arc is less than half a
  /// turn, so it starts at whichever end makes the counter-clockwise sweep the short one.
  void arc(std::string_view layer, const PaperArc& a) {
    const Point2 c = to_plan_(a.centre);
    const Point2 f = to_plan_(a.from);
    const Point2 t = to_plan_(a.to);
    const double degrees = 180.0 / std::numbers::pi;
    double start = std::atan2(f.y - c.y, f.x - c.x) * degrees;
    double end = std::atan2(t.y - c.y, t.x - c.x) * degrees;
    if (std::fmod(end - start + 720.0, 360.0) > 180.0) std::swap(start, end);
    head("ARC", layer);
    w_.group(100, "AcDbCircle");
    point3(10, c);
    w_.group(40, a.radius / to_plan_.mm_per_m);
    w_.group(100, "AcDbArc");
    w_.group(50, std::fmod(start + 360.0, 360.0));
    w_.group(51, std::fmod(end + 360.0, 360.0));
  }

  void text(std::string_view layer, const PaperText& t) {
    const Point2 at = to_plan_(t.at);
    head("TEXT", layer);
    w_.group(100, "AcDbText");
    point3(10, at);
    w_.group(40, t.size / to_plan_.mm_per_m);
    w_.group(1, t.text);
    // Clockwise on paper (y down) is clockwise in the plan too; DXF angles turn the other way.
    if (t.rotate_deg != 0.0) w_.group(50, std::fmod(360.0 - t.rotate_deg, 360.0));
    const int justify = t.anchor == TextAnchor::start ? 0 : t.anchor == TextAnchor::middle ? 1 : 2;
    if (justify != 0) {
      w_.group(72, justify);
      point3(11, at);
    }
    w_.group(100, "AcDbText");
  }
};

/// One symbol table: its head, the entries `write_entries` adds, its end.
template <class F>
void table(DxfWriter& w, std::string_view name, std::string_view handle, int count,
           F write_entries) {
  w.group(0, "TABLE");
  w.group(2, name);
  w.group(5, handle);
  w.group(330, "0");
  w.group(100, "AcDbSymbolTable");
  if (name == "DIMSTYLE") w.group(100, "AcDbDimStyleTable");
  w.group(70, count);
  write_entries();
  w.group(0, "ENDTAB");
}

void entry(DxfWriter& w, std::string_view type, std::string_view table_handle,
           std::string_view subclass, std::string_view name, int handle_code = 5) {
  w.group(0, type);
  w.handle(handle_code);
  w.group(330, table_handle);
  w.group(100, "AcDbSymbolTableRecord");
  w.group(100, subclass);
  w.group(2, name);
  w.group(70, 0);
}

void linetype(DxfWriter& w, std::string_view name, std::string_view description,
              const std::vector<double>& dashes) {
  entry(w, "LTYPE", "5", "AcDbLinetypeTableRecord", name);
  w.group(3, description);
  w.group(72, 65);
  w.group(73, static_cast<int>(dashes.size()));
  double total = 0.0;
  for (const double d : dashes) total += std::abs(d);
  w.group(40, total);
  for (const double d : dashes) w.group(49, d), w.group(74, 0);
}

/// The tables (fixed handles 2..9 and 1F) with the symbols the entities use.
void write_tables(DxfWriter& w, double mm_per_m) {
  w.group(0, "SECTION");
  w.group(2, "TABLES");
  table(w, "VPORT", "8", 0, [] {});
  table(w, "LTYPE", "5", 4, [&] {
    linetype(w, "ByBlock", "", {});
    linetype(w, "ByLayer", "", {});
    linetype(w, "Continuous", "Solid line", {});
    // 2 mm dashes and 1 mm gaps on paper, at the drawing's scale.
    linetype(w, "DASHED", "Dashed __ __ __", {2.0 / mm_per_m, -1.0 / mm_per_m});
  });
  table(w, "LAYER", "2", 1 + static_cast<int>(std::size(kDxfLayers)), [&] {
    for (std::string_view name : {std::string_view("0")})
      entry(w, "LAYER", "2", "AcDbLayerTableRecord", name), w.group(62, 7),
          w.group(6, "Continuous");
    const int colours[] = {7, 8, 8, 5,
                           3, 1, 2};  // ACI: white, grey, grey, blue, green, red, yellow
    for (std::size_t i = 0; i < std::size(kDxfLayers); ++i) {
      entry(w, "LAYER", "2", "AcDbLayerTableRecord", kDxfLayers[i]);
      w.group(62, colours[i]);
      w.group(6, std::string_view(kDxfLayers[i]) == "WALLS_ABOVE" ? "DASHED" : "Continuous");
    }
  });
  table(w, "STYLE", "3", 1, [&] {
    entry(w, "STYLE", "3", "AcDbTextStyleTableRecord", "Standard");
    w.group(40, 0.0), w.group(41, 1.0), w.group(50, 0.0), w.group(71, 0), w.group(42, 0.2);
    w.group(3, "txt"), w.group(4, "");
  });
  table(w, "VIEW", "6", 0, [] {});
  table(w, "UCS", "7", 0, [] {});
  table(w, "APPID", "9", 1, [&] { entry(w, "APPID", "9", "AcDbRegAppTableRecord", "ACAD"); });
  table(w, "DIMSTYLE", "A", 1,
        [&] { entry(w, "DIMSTYLE", "A", "AcDbDimStyleTableRecord", "Standard", 105); });
  table(w, "BLOCK_RECORD", "1", 2, [&] {
    for (const char* name : {"*Model_Space", "*Paper_Space"}) {
      w.group(0, "BLOCK_RECORD");
      w.group(5, std::string_view(name[1] == 'M' ? kModelSpace : "1E"));
      w.group(330, "1");
      w.group(100, "AcDbSymbolTableRecord");
      w.group(100, "AcDbBlockTableRecord");
      w.group(2, name);
    }
  });
  w.group(0, "ENDSEC");
}

void write_blocks(DxfWriter& w) {
  w.group(0, "SECTION");
  w.group(2, "BLOCKS");
  for (const char* name : {"*Model_Space", "*Paper_Space"}) {
    const std::string_view owner = name[1] == 'M' ? kModelSpace : "1E";
    // BLOCK and ENDBLK each: a handle, the owner, paper space or not, layer 0, the subclass.
    auto entity = [&](const char* type, const char* subclass) {
      w.group(0, type);
      w.handle();
      w.group(330, owner);
      w.group(100, "AcDbEntity");
      if (name[1] == 'P') w.group(67, 1);
      w.group(8, "0");
      w.group(100, subclass);
    };
    entity("BLOCK", "AcDbBlockBegin");
    w.group(2, name);
    w.group(70, 0);
    w.group(10, 0.0), w.group(20, 0.0), w.group(30, 0.0);
    w.group(3, name);
    w.group(1, "");
    entity("ENDBLK", "AcDbBlockEnd");
  }
  w.group(0, "ENDSEC");
}

void dictionary(DxfWriter& w, std::string_view handle, std::string_view owner) {
  w.group(0, "DICTIONARY");
  w.group(5, handle);
  w.group(330, owner);
  w.group(100, "AcDbDictionary");
  w.group(281, 1);
}

/// The root dictionary (C) holding the empty ACAD_GROUP dictionary (D), as AutoCAD expects.
void write_objects(DxfWriter& w) {
  w.group(0, "SECTION");
  w.group(2, "OBJECTS");
  dictionary(w, "C", "0");
  w.group(3, "ACAD_GROUP");
  w.group(350, "D");
  dictionary(w, "D", "C");
  w.group(0, "ENDSEC");
}

}  // namespace

std::string format_floor_plan_dxf(const FloorPlanDrawing& drawing) {
  DxfWriter body;
  write_tables(body, drawing.mm_per_m);
  write_blocks(body);
  body.group(0, "SECTION");
  body.group(2, "ENTITIES");
  PlanDxf(body, drawing).write_entities();
  body.group(0, "ENDSEC");
  write_objects(body);
  body.group(0, "EOF");
  // The header comes first but names the next free handle, known only now.
  DxfWriter header;
  header.group(0, "SECTION");
  header.group(2, "HEADER");
  header.group(9, "$ACADVER"), header.group(1, "AC1015");
  header.group(9, "$HANDSEED"),
      header.group(5, std::string_view(fmt::format("{:X}", body.next_handle())));
  header.group(9, "$INSUNITS"), header.group(70, 6);     // metres
  header.group(9, "$MEASUREMENT"), header.group(70, 1);  // metric
  header.group(9, "$LUNITS"), header.group(70, 2);       // decimal
  header.group(0, "ENDSEC");
  return header.text() + body.text();
}

Status write_floor_plan_dxf(const FloorPlanDrawing& drawing, const std::filesystem::path& path) {
  return write_file_atomically(path, format_floor_plan_dxf(drawing));
}

}  // namespace roomcad
