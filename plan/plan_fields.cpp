// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/plan_fields.h"

#include <algorithm>

namespace roomcad {
namespace {

using enum Unit;
using enum Presence;

// Hints say what a value looks like; they appear in `add --help` and in type errors.
constexpr std::string_view kId = "a unique id";
constexpr std::string_view kPoint = "x,y in metres";
constexpr std::string_view kMetres = "metres";
constexpr std::string_view kColour = "#rrggbb";

const Field<Site> kSiteFields[] = {
    {"origin", &Site::origin, metre, Check::finite, optional, 0, kPoint},
    {"cells", &Site::cells, none, Check::positive_cells, optional, 12, "nx,ny tiles"},
    {"cell_size", &Site::cell_size, metre, Check::positive, optional, 1.0, kMetres},
    {"max_height", &Site::max_height, metre, Check::positive, optional, 6.0, kMetres},
    {"tolerance", &Site::tolerance, metre, Check::positive, optional, 1e-6, kMetres},
    {"floor_color", &Site::floor_color, none, Check::any, optional, 0, kColour},
    {"chord_tolerance", &Site::chord_tolerance, metre, Check::positive, version2, 0.001, kMetres},
    {"location", &Site::location, none, Check::any, version2, 0,
     "latitude,longitude,utc_offset: degrees north, degrees east, hours ahead of UTC"},
    {"north", &Site::north, degree, Check::finite, version2, 0,
     "degrees from the plan's +y axis to true north, counter-clockwise"},
};

const Field<GeoLocation> kGeoLocationFields[] = {
    {"latitude", &GeoLocation::latitude, degree, Check::latitude, required, 55.75, "degrees north"},
    {"longitude", &GeoLocation::longitude, degree, Check::longitude, required, 37.62,
     "degrees east"},
    {"utc_offset", &GeoLocation::utc_offset, none, Check::utc_offset, optional, 3,
     "hours ahead of UTC"},
};

const Field<Level> kLevelFields[] = {
    {"id", &Level::id, none, Check::any, required, 0, kId},
    {"elevation", &Level::elevation, metre, Check::finite, required, 0.0,
     "z of its floor in metres"},
    {"height", &Level::height, metre, Check::positive, optional, 2.8, "floor to floor, metres"},
};

const Field<Wall> kWallFields[] = {
    {"id", &Wall::id, none, Check::any, required, 0, kId},
    {"level", &Wall::level, none, Check::any, version2, 0, "id of its level"},
    {"from", &Wall::from, metre, Check::finite, required, 0, "the start of the centre line, x,y"},
    {"to", &Wall::to, metre, Check::finite, required, 0, "the end of the centre line, x,y"},
    {"thickness", &Wall::thickness, metre, Check::positive, optional, 0.25, kMetres},
    {"height", &Wall::height, metre, Check::positive, optional, 2.8, "metres (at from)"},
    {"base", &Wall::base, metre, Check::level_offset, optional, 0.0, "metres above its level"},
    {"height_at_end", &Wall::height_at_end, metre, Check::positive, version2, 2.8,
     "metres at to (a sloped top)"},
    {"arc_extent", &Wall::arc_extent, degree, Check::turn, version2, 90,
     "degrees turned from from to to (an arc)"},
    {"color", &Wall::color, none, Check::any, optional, 0, kColour},
};

const Field<Opening> kOpeningFields[] = {
    {"id", &Opening::id, none, Check::any, required, 0, kId},
    {"type", &Opening::type, none, Check::any, optional, 0, "door or window"},
    {"wall", &Opening::wall, none, Check::any, required, 0, "the id of the wall it is cut in"},
    {"offset", &Opening::offset, metre, Check::finite, required, 0,
     "its start along the wall, metres from the wall's from"},
    {"width", &Opening::width, metre, Check::positive, optional, 0.9, kMetres},
    {"height", &Opening::height, metre, Check::positive, optional, 2.1, kMetres},
    {"sill", &Opening::sill, metre, Check::non_negative, optional, 0.0,
     "metres above its wall's base"},
    {"hinge", &Opening::hinge, none, Check::any, optional, 0, "left or right"},
    {"swing", &Opening::swing, none, Check::any, optional, 0, "in or out"},
    {"shape", &Opening::shape, none, Check::polygon, version2, 0,
     "u,v;u,v;... in the unit square of its rectangle"},
};

const Field<Slab> kSlabFields[] = {
    {"id", &Slab::id, none, Check::any, required, 0, kId},
    {"level", &Slab::level, none, Check::any, version2, 0, "id of its level"},
    {"outline", &Slab::outline, metre, Check::polygon, required, 0, "x,y;x,y;... in metres"},
    {"holes", &Slab::holes, metre, Check::polygons, version2, 0, "x,y;x,y;...|x,y;... in metres"},
    {"top", &Slab::top, metre, Check::finite, optional, 0.0, "metres above its level"},
    {"thickness", &Slab::thickness, metre, Check::positive, optional, 0.2, kMetres},
    {"color", &Slab::color, none, Check::any, optional, 0, kColour},
};

const Field<Light> kLightFields[] = {
    {"id", &Light::id, none, Check::any, required, 0, kId},
    {"type", &Light::type, none, Check::any, optional, 0, "directional"},
    {"direction", &Light::direction, none, Check::non_zero, optional, 0,
     "x,y,z from the light into the scene"},
    {"intensity", &Light::intensity, none, Check::finite, optional, 1.0, "a number"},
    {"ambient", &Light::ambient, none, Check::unit_interval, optional, 0.25, "0 to 1"},
};
const Field<RoomLabel> kRoomLabelFields[] = {
    {"id", &RoomLabel::id, none, Check::any, required, 0, kId},
    {"level", &RoomLabel::level, none, Check::any, version2, 0, "id of its level"},
    {"at", &RoomLabel::at, metre, Check::finite, required, 0, "a point inside the room, x,y"},
    {"name", &RoomLabel::name, none, Check::any, required, 0,
     "what the room is: Kitchen, Bedroom, Bath, Hall, ..."},
};

const Field<Obstruction> kObstructionFields[] = {
    {"id", &Obstruction::id, none, Check::any, required, 0, kId},
    {"outline", &Obstruction::outline, metre, Check::polygon, required, 0,
     "x,y;x,y;... in metres, counter-clockwise"},
    {"base", &Obstruction::base, metre, Check::finite, optional, 0.0, "metres above z = 0"},
    {"height", &Obstruction::height, metre, Check::positive, required, 10.0, kMetres},
};

const Field<Camera> kCameraFields[] = {
    {"id", &Camera::id, none, Check::any, required, 0, kId},
    {"projection", &Camera::projection, none, Check::any, optional, 0,
     "perspective or orthographic"},
    {"eye", &Camera::eye, metre, Check::finite, required, 0, "where it is, x,y,z in metres"},
    {"target", &Camera::target, metre, Check::finite, required, 0,
     "the point it looks at, x,y,z in metres"},
    {"up", &Camera::up, none, Check::non_zero, optional, 0, "x,y,z"},
    {"fov_deg", &Camera::fov_deg, degree, Check::lens, optional, 50, "degrees"},
    {"view_height", &Camera::view_height, metre, Check::lens, optional, 10.0, kMetres},
};

template <class Object>
bool uses_version2_fields(const std::vector<Object>& objects) {
  const auto fields = fields_of<Object>();
  return std::any_of(objects.begin(), objects.end(), [&](const Object& o) {
    return std::any_of(fields.begin(), fields.end(), [&](const Field<Object>& f) {
      return f.presence == Presence::version2 && is_present(o, f);
    });
  });
}

}  // namespace

template <>
std::span<const Field<Site>> fields_of<Site>() {
  return kSiteFields;
}
template <>
std::span<const Field<GeoLocation>> fields_of<GeoLocation>() {
  return kGeoLocationFields;
}
template <>
std::span<const Field<Level>> fields_of<Level>() {
  return kLevelFields;
}
template <>
std::span<const Field<Wall>> fields_of<Wall>() {
  return kWallFields;
}
template <>
std::span<const Field<Opening>> fields_of<Opening>() {
  return kOpeningFields;
}
template <>
std::span<const Field<Slab>> fields_of<Slab>() {
  return kSlabFields;
}
template <>
std::span<const Field<RoomLabel>> fields_of<RoomLabel>() {
  return kRoomLabelFields;
}
template <>
std::span<const Field<Obstruction>> fields_of<Obstruction>() {
  return kObstructionFields;
}
template <>
std::span<const Field<Light>> fields_of<Light>() {
  return kLightFields;
}
template <>
std::span<const Field<Camera>> fields_of<Camera>() {
  return kCameraFields;
}

bool uses_version2(const Plan& plan) {
  return !plan.levels.empty() || !plan.slabs.empty() || !plan.obstructions.empty() ||
         uses_version2_fields(std::vector<Site>{plan.site}) || uses_version2_fields(plan.walls) ||
         uses_version2_fields(plan.openings) || uses_version2_fields(plan.rooms);
}

}  // namespace roomcad
