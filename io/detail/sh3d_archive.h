// Reading the `Home.xml` entry of a Sweet Home 3D `.sh3d` file (a ZIP archive), with libzip.
#pragma once

#include <filesystem>
#include <string>

#include "io/result.h"

namespace roomcad::sh3d {

/// @return true when `bytes` starts like a ZIP archive (a local file header, "PK\3\4").
[[nodiscard]] bool is_zip_data(std::string_view bytes);

/// Extracts the `Home.xml` entry of the archive at `path`.
/// @return its text, or an error naming the file and the reason: not a ZIP archive, no
///   `Home.xml` entry, an entry that cannot be read. O(size of the entry).
[[nodiscard]] Result<std::string> read_home_xml_entry(const std::filesystem::path& path);

}  // namespace roomcad::sh3d
