// SPDX-License-Identifier: GPL-3.0-or-later
// roomcad.sun and Plan.sun: where the sun is at a site and time, as `roomcad sun --format json`
// says it (docs/plan-format.md, "Sun and sunlight").
#include <cmath>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "daylight/insolation.h"
#include "daylight/sun_position.h"
#include "python/py_error.h"
#include "python/py_site.h"
#include "python/py_types.h"
#include "solid/build_model.h"

namespace py = pybind11;

namespace roomcad::python {
namespace {

py::object clock_or_none(const std::optional<UtcSeconds>& t, double offset) {
  return t ? py::object(py::str(format_clock(*t, offset))) : py::object(py::none());
}

/// The sun at `place` and time text `at`, in a plan whose north is `north`, as a dict.
py::dict sun_dict(const GeoLocation& place, const std::string& at, double north) {
  const UtcSeconds t = take(parse_site_time(at, place.utc_offset));
  const SunPosition sun = sun_position(place, t);
  const Vec3 d = sun_direction_in_plan(sun, north);
  const auto day = local_day(t, place.utc_offset);
  const SunDay s = sun_day(place, day);
  py::dict out;
  out["azimuth"] = sun.azimuth;
  out["elevation"] = sun.elevation;
  out["direction"] = py::make_tuple(d.x, d.y, d.z);
  out["sunrise"] = clock_or_none(s.sunrise, place.utc_offset);
  out["solar_noon"] = format_clock(s.solar_noon, place.utc_offset);
  out["sunset"] = clock_or_none(s.sunset, place.utc_offset);
  return out;
}

/// The day's direct sun as `roomcad insolation --format json` prints it.
py::dict insolation_dict(const InsolationDay& day) {
  const double offset = day.place.utc_offset;
  py::list rooms;
  for (const RoomSun& room : day.rooms) {
    py::list windows;
    for (const WindowSun& w : room.windows) {
      py::list intervals;
      for (const auto& [a, b] : w.intervals)
        intervals.append(
            py::make_tuple(format_clock(a, offset), format_clock(b, offset, day.date)));
      py::dict window;
      window["id"] = w.id;
      window["intervals"] = intervals;
      window["continuous_hours"] = w.continuous_hours;
      window["total_hours"] = w.total_hours;
      windows.append(window);
    }
    py::dict r;
    r["room"] = room.room;
    r["name"] = room.name;
    r["level"] = room.level;
    r["area"] = room.area;
    r["windows"] = windows;
    r["best_window"] =
        room.best_window.empty() ? py::object(py::none()) : py::object(py::str(room.best_window));
    r["continuous_hours"] = room.continuous_hours;
    r["total_hours"] = room.total_hours;
    rooms.append(r);
  }
  py::dict out;
  out["date"] = format_site_date(day.date);
  out["utc_offset"] = offset;
  out["latitude"] = day.place.latitude;
  out["longitude"] = day.place.longitude;
  out["rooms"] = rooms;
  return out;
}

}  // namespace

const GeoLocation& site_location(const Plan& plan, std::string_view what) {
  if (!plan.site.location)
    raise(Error{Code::usage_error,
                std::string(what) +
                    ": the plan does not say where its site is (no site.location); set it with "
                    "plan.set('site', 'location', 'LAT,LON,UTC_OFFSET')"});
  return *plan.site.location;
}

void register_daylight(py::module_& m, py::class_<PyPlan>& plan) {
  m.def(
      "sun",
      [](const std::string& at, double latitude, double longitude, double utc_offset) {
        if (!(latitude >= -90 && latitude <= 90) || !(longitude >= -180 && longitude <= 180) ||
            !(utc_offset >= -12 && utc_offset <= 14))
          raise(Error{Code::usage_error,
                      "sun: latitude must be in [-90, 90], longitude in [-180, 180], "
                      "utc_offset in [-12, 14]"});
        return sun_dict(GeoLocation{latitude, longitude, utc_offset, {}}, at, 0.0);
      },
      py::arg("at"), py::arg("latitude"), py::arg("longitude"), py::arg("utc_offset") = 0.0,
      "Where the sun is, as `roomcad sun --latitude --longitude --format json`: a dict of\n"
      "azimuth (degrees clockwise from north), elevation (geometric), direction (towards the\n"
      "sun, north +y), sunrise, solar_noon and sunset ('HH:MM:SS' local, None in polar day or\n"
      "night).\n"
      "@param at  'YYYY-MM-DDTHH:MM[:SS]' local at utc_offset, or with its own offset ('Z')\n"
      "@raise roomcad.Error usage_error for a bad time or place");
  plan.def(
      "sun",
      [](const PyPlan& self, const std::string& at) {
        return sun_dict(site_location(self.plan, "sun"), at, self.plan.site.north.value_or(0.0));
      },
      py::arg("at"),
      "Where the sun is at the plan's site.location at local time `at`, as `roomcad sun PLAN\n"
      "--format json`: the direction is in the plan's coordinates (site.north applied).\n"
      "@raise roomcad.Error usage_error without site.location or for a bad time");
  plan.def(
      "insolation",
      [](const PyPlan& self, const std::string& date, bool force, int threads) {
        (void)site_location(self.plan, "insolation");
        const CivilDay day = take(parse_site_date(date));
        require_valid(self, force, "insolation");
        py::gil_scoped_release free;
        BuildOptions build;
        build.threads = threads;
        const Model model = build_model(self.plan, build);
        InsolationOptions options;
        options.threads = threads;
        InsolationDay result = insolation(self.plan, model.walls, day, options);
        py::gil_scoped_acquire held;
        return insolation_dict(result);
      },
      py::arg("date"), py::arg("force") = false, py::arg("threads") = 0,
      "The direct sun each room's windows get on `date` ('YYYY-MM-DD', local), as `roomcad\n"
      "insolation PLAN --date D --format json` prints it: a dict of date, utc_offset and rooms,\n"
      "each with its windows' intervals ('HH:MM:SS' pairs), continuous_hours and total_hours.\n"
      "Releases the GIL.\n"
      "@raise roomcad.Error usage_error without site.location or for a bad date; the plan's\n"
      "first error unless force");
}

}  // namespace roomcad::python
