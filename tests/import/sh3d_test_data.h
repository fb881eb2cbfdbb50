// SPDX-License-Identifier: GPL-3.0-or-later
// Test data for the Sweet Home 3D importer: the real homes bundled in examples/sweethome3d/homes
// (THIRD_PARTY.md), and a plain-text reading of their XML that does not share code with the
// importer.
#pragma once

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "import/sweethome3d_import.h"
#include "support/run_command.h"

namespace roomcad::sh3d_test {

namespace fs = std::filesystem;

inline const fs::path kData = test::source_dir() / "examples" / "sweethome3d" / "homes";

inline std::vector<fs::path> all_homes() {
  std::vector<fs::path> homes;
  for (const char* dir : {"eteks-example-homes", "edge-cases"})
    for (const auto& e : fs::directory_iterator(kData / dir))
      if (e.path().extension() == ".xml") homes.push_back(e.path());
  std::sort(homes.begin(), homes.end());
  return homes;
}

inline std::string read_text(const fs::path& p) { return test::read_bytes(p); }

using Attributes = std::map<std::string, std::string>;

/// Every `<tag ...>` element's attributes, in file order.
inline std::vector<Attributes> elements(const std::string& xml, const std::string& tag) {
  std::vector<Attributes> out;
  const std::regex element("<" + tag + R"(\s([^>]*)>)");
  const std::regex attribute(R"re((\w+)='([^']*)')re");
  for (std::sregex_iterator e(xml.begin(), xml.end(), element), end; e != end; ++e) {
    Attributes a;
    const std::string body = (*e)[1];
    for (std::sregex_iterator m(body.begin(), body.end(), attribute); m != end; ++m)
      a[(*m)[1]] = (*m)[2];
    out.push_back(std::move(a));
  }
  return out;
}

inline Sh3dImport import_or_fail(const fs::path& p, const Sh3dImportOptions& options = {}) {
  Result<Sh3dImport> r = import_sweethome3d_file(p, options);
  EXPECT_TRUE(r.ok()) << r.error();
  return r.ok() ? std::move(r).value() : Sh3dImport{};
}

}  // namespace roomcad::sh3d_test
