// SPDX-License-Identifier: GPL-3.0-or-later
// The Sweet Home 3D compass as the plan's site: latitude, longitude and north from the XML
// (read here with plain text matching), the time zone's offset at the observer camera's time,
// and a zone the system does not know.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "import/detail/time_zone.h"
#include "import/sh3d_test_data.h"
#include "import/sweethome3d_import.h"

namespace roomcad {
namespace {

using namespace sh3d_test;

double degrees(const std::string& radians) { return std::stod(radians) * 180.0 / std::numbers::pi; }

TEST(Sh3dCompass, EveryHomesCompassIsItsSite) {
  for (const char* name : {"eteks-example-homes/Studio", "eteks-example-homes/4-BedroomHouse",
                           "community-homes/arif-putra-pertama-1"}) {
    SCOPED_TRACE(name);
    const fs::path home = kData / (std::string(name) + ".Home.xml");
    const Sh3dImport imported = import_or_fail(home);
    const std::vector<Attributes> compass = elements(read_text(home), "compass");
    ASSERT_EQ(compass.size(), 1u);
    const Site& site = imported.plan.site;
    ASSERT_TRUE(site.location);
    EXPECT_NEAR(site.location->latitude, degrees(compass[0].at("latitude")), 1e-4);
    EXPECT_NEAR(site.location->longitude, degrees(compass[0].at("longitude")), 1e-4);
    // Clockwise on the screen is counter-clockwise negated.
    const double north = -degrees(compass[0].at("northDirection"));
    EXPECT_NEAR(std::remainder(*site.north - north, 360.0), 0.0, 1e-4);
    EXPECT_GT(*site.north, -180.0);
    EXPECT_LE(*site.north, 180.0);
  }
}

TEST(Sh3dCompass, TheOffsetIsTheZonesAtTheCamerasTime) {
  // Studio's observer camera shows 2017-04-06 12:00 UTC: Paris is on summer time (+2).
  const Sh3dImport studio = import_or_fail(kData / "eteks-example-homes" / "Studio.Home.xml");
  EXPECT_EQ(studio.plan.site.location->utc_offset, 2.0);
  const Sh3dImport jakarta =
      import_or_fail(kData / "community-homes" / "arif-putra-pertama-1.Home.xml");
  EXPECT_EQ(jakarta.plan.site.location->utc_offset, 7.0);
}

TEST(Sh3dCompass, ZoneFilesGiveStandardAndSummerTime) {
  EXPECT_EQ(sh3d::zone_utc_offset("Europe/Paris", 1767225600), 1.0);  // 2026-01-01
  EXPECT_EQ(sh3d::zone_utc_offset("Europe/Paris", 1782864000), 2.0);  // 2026-07-01
  EXPECT_EQ(sh3d::zone_utc_offset("Asia/Kolkata", 1782864000), 5.5);
  EXPECT_EQ(sh3d::zone_utc_offset("America/New_York", 1767225600), -5.0);
  EXPECT_FALSE(sh3d::zone_utc_offset("Mars/Olympus_Mons", 0));
  EXPECT_FALSE(sh3d::zone_utc_offset("../../etc/passwd", 0));
  EXPECT_FALSE(sh3d::zone_utc_offset("", 0));
}

TEST(Sh3dCompass, AnUnknownZoneTakesTheLongitudesHourWithAWarning) {
  const std::string xml =
      "<home><compass latitude='0.9' longitude='0.5' northDirection='0' timeZone='Nowhere/Land'/>"
      "<wall id='w' xStart='0' yStart='0' xEnd='400' yEnd='0' thickness='20' height='250'/>"
      "</home>";
  const Result<Sh3dImport> imported = import_sweethome3d_text(xml, "nowhere.xml", {});
  ASSERT_TRUE(imported) << imported.error().message;
  const GeoLocation& place = *imported.value().plan.site.location;
  EXPECT_EQ(place.utc_offset, 2.0);  // 28.6 degrees east
  bool warned = false;
  for (const Diagnostic& d : imported.value().warnings.items)
    warned = warned || (d.code == Code::import_approximated &&
                        d.message.find("Nowhere/Land") != std::string::npos);
  EXPECT_TRUE(warned);
}

}  // namespace
}  // namespace roomcad
