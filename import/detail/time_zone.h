// SPDX-License-Identifier: GPL-3.0-or-later
// A named time zone's offset from UTC at a moment, read from the system's zone files
// (/usr/share/zoneinfo, Debian's tzdata): how a Sweet Home 3D compass's `timeZone` becomes a
// plan's `site.location.utc_offset`.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace roomcad::sh3d {

/// @return the offset in hours of zone `name` ("Europe/Paris") from UTC at `unix_seconds`, or
///         nothing when the name is not a zone of the system (or not a safe file name) or its
///         file is not a TZif file. Times past the file's last transition keep its offset.
///         O(size of the zone file).
[[nodiscard]] std::optional<double> zone_utc_offset(std::string_view name,
                                                    std::int64_t unix_seconds);

}  // namespace roomcad::sh3d
