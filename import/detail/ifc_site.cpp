// SPDX-License-Identifier: GPL-3.0-or-later
// Where the model stands: IfcSite's RefLatitude and RefLongitude as the plan's site.location,
// and the model context's TrueNorth as site.north.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "import/detail/ifc_elements.h"

namespace roomcad::ifc {
namespace {

using step::Value;

/// @return the degrees of an IfcCompoundPlaneAngleMeasure (degrees, minutes, seconds and
///   millionths of a second, all of one sign), or nothing for a value that is not one.
std::optional<double> compound_angle(const Value& v) {
  const std::vector<Value>& parts =
      v.kind == Value::Kind::typed && !v.items.empty() ? v.items[0].items : v.items;
  if (v.kind != Value::Kind::list && v.kind != Value::Kind::typed) return std::nullopt;
  if (parts.size() < 3) return std::nullopt;
  const double scale[] = {1.0, 60.0, 3600.0, 3600e6};
  double degrees = 0.0;
  for (std::size_t i = 0; i < parts.size() && i < 4; ++i) {
    if (!parts[i].is_number()) return std::nullopt;
    degrees += parts[i].number / scale[i];
  }
  return degrees;
}

/// @return the TrueNorth of the 3D model context as degrees counter-clockwise from +y.
std::optional<double> true_north(const ImportState& s) {
  for (const step::Instance& e : s.file.instances) {
    if (e.type != "IFCGEOMETRICREPRESENTATIONCONTEXT" || Geometry::param(e, 1).text != "Model")
      continue;
    const step::Instance* d = s.geometry.get(Geometry::param(e, 5));
    if (!d || d->type != "IFCDIRECTION") continue;
    const auto& c = Geometry::param(*d, 0).items;
    if (c.size() < 2 || !c[0].is_number() || !c[1].is_number() ||
        !(std::hypot(c[0].number, c[1].number) > 0.0))
      continue;
    const double north = std::atan2(-c[0].number, c[1].number) * 180.0 / std::numbers::pi;
    return std::round(north * 1e9) / 1e9 + 0.0;
  }
  return std::nullopt;
}

}  // namespace

void import_site(ImportState& s) {
  if (const auto north = true_north(s); north && *north != 0.0) s.plan.site.north = *north;
  for (const step::Instance& e : s.file.instances) {
    if (e.type != "IFCSITE") continue;
    const auto latitude = compound_angle(Geometry::param(e, 9));
    const auto longitude = compound_angle(Geometry::param(e, 10));
    if (!latitude || !longitude) continue;
    if (std::abs(*latitude) > 90.0 || std::abs(*longitude) > 180.0) {
      s.warn(Code::import_skipped_element, e,
             fmt::format("its RefLatitude {} or RefLongitude {} is out of range; the plan has no "
                         "site.location",
                         *latitude, *longitude));
      return;
    }
    // IFC gives no time zone: the longitude's nautical one stands in for it.
    const double offset = std::clamp(std::round(*longitude / 15.0), -12.0, 14.0) + 0.0;
    s.plan.site.location = GeoLocation{.latitude = std::round(*latitude * 1e9) / 1e9,
                                       .longitude = std::round(*longitude * 1e9) / 1e9,
                                       .utc_offset = offset};
    s.read.insert(e.id);
    s.add_warning(Code::import_approximated, e,
                  fmt::format("its RefLatitude and RefLongitude are site.location; IFC gives no "
                              "time zone, so utc_offset is the longitude's nautical one ({:+g} h): "
                              "`roomcad set PLAN site location=LAT,LON,UTC_OFFSET` sets the local "
                              "one",
                              offset),
                  {});
    return;
  }
}

}  // namespace roomcad::ifc
