// SPDX-License-Identifier: GPL-3.0-or-later
// Times at a site: ISO 8601 local times and dates, read in the site's offset unless they carry
// their own, and clock times written back.
#include <gtest/gtest.h>

#include "daylight/site_time.h"

namespace roomcad {
namespace {

TEST(SiteTime, LocalTimesReadInTheSitesOffsetUnlessTheyCarryTheirOwn) {
  const UtcSeconds utc = 1776868200;  // 2026-04-22T14:30:00Z
  EXPECT_EQ(parse_site_time("2026-04-22T14:30", 0).value(), utc);
  EXPECT_EQ(parse_site_time("2026-04-22T17:30", 3).value(), utc);
  EXPECT_EQ(parse_site_time("2026-04-22T17:30:00", 3).value(), utc);
  EXPECT_EQ(parse_site_time("2026-04-22T14:30Z", 3).value(), utc);
  EXPECT_EQ(parse_site_time("2026-04-22T20:00+05:30", 3).value(), utc);
  EXPECT_EQ(parse_site_time("2026-04-22T09:30-0500", 3).value(), utc);
  EXPECT_EQ(parse_site_time("1950-01-01T00:00Z", 0).value(), -631152000);
}

TEST(SiteTime, MalformedTimesAndDatesAreUsageErrorsNamingTheText) {
  for (const char* bad : {"2026-04-31T10:00", "2026-02-29T10:00", "2026-04-22", "2026-04-22T24:00",
                          "2026-04-22T10:00+15:00", "2026-04-22T10:00:60", "22/04/2026 10:00"}) {
    const Result<UtcSeconds> t = parse_site_time(bad, 0);
    ASSERT_FALSE(t) << bad;
    EXPECT_EQ(t.error().code, Code::usage_error);
    EXPECT_NE(t.error().message.find(bad), std::string::npos);
  }
  EXPECT_TRUE(parse_site_time("2024-02-29T10:00", 0));
  EXPECT_FALSE(parse_site_date("2026-13-01"));
  EXPECT_EQ(parse_site_date("2026-04-22").value(), civil_day(2026, 4, 22));
}

TEST(SiteTime, DatesAndClocksWriteBack) {
  for (const CivilDay d : {-7305, 0, 20565, 47482})
    EXPECT_EQ(parse_site_date(format_site_date(d)).value(), d);
  EXPECT_EQ(format_site_date(civil_day(2026, 4, 22)), "2026-04-22");
  const UtcSeconds midnight = local_midnight(civil_day(2026, 4, 22), 3);
  EXPECT_EQ(format_clock(midnight + 5 * 3600 + 14 * 60 + 19.4, 3), "05:14:19");
  EXPECT_EQ(format_clock(midnight + 86400, 3), "00:00:00");
  EXPECT_EQ(format_clock(midnight + 86400, 3, civil_day(2026, 4, 22)), "24:00:00");
}

}  // namespace
}  // namespace roomcad
