// SPDX-License-Identifier: GPL-3.0-or-later
// Reading the `Home.xml` entry of a Sweet Home 3D `.sh3d` file (a ZIP archive), with libzip.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/error.h"

namespace roomcad::sh3d {

/// @return true when `bytes` starts like a ZIP archive (a local file header, "PK\3\4").
[[nodiscard]] bool is_zip_data(std::string_view bytes);

/// Largest `Home.xml` entry read (the eteks example homes hold under 200 KB): the archive
/// declares the entry's size, and a few hostile bytes could otherwise claim gigabytes.
inline constexpr std::uint64_t kMaxHomeXmlBytes = 256u << 20;

/// Extracts the `Home.xml` entry of the archive at `path`.
/// @return its text, or an error naming the file and the reason: not a ZIP archive, no
///   `Home.xml` entry, an entry that cannot be read or is larger than kMaxHomeXmlBytes.
///   O(size of the entry).
[[nodiscard]] Result<std::string> read_home_xml_entry(const std::filesystem::path& path);

}  // namespace roomcad::sh3d
