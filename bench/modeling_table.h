// SPDX-License-Identifier: GPL-3.0-or-later
// The modeling benchmark's report: Google Benchmark runs named "<path>/<n>" (path: fast, cgal,
// nef, openscad) gathered into one row per scene, written as CSV and as a Markdown table.
// The CSV columns are documented in bench/modeling_report.sh and must stay stable.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "io/atomic_write.h"

namespace roomcad::bench {

/// Keeps every run while printing them as usual.
class CollectingReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    runs_.insert(runs_.end(), runs.begin(), runs.end());
    ConsoleReporter::ReportRuns(runs);
  }
  [[nodiscard]] const std::vector<Run>& runs() const { return runs_; }

 private:
  std::vector<Run> runs_;
};

inline constexpr const char* kPaths[] = {"fast", "cgal", "nef", "openscad"};

struct PathCell {
  bool ran = false;
  double ms = 0.0, triangles = 0.0, volume_error = 0.0, bytes = 0.0, build_ms = 0.0;
};

struct TableRow {
  int n = 0;
  double walls = 0.0, openings = 0.0;
  std::map<std::string, PathCell> cells;  ///< by path name
};

/// @return one row per grid size, ascending. O(runs log runs).
inline std::vector<TableRow> make_table(
    const std::vector<benchmark::BenchmarkReporter::Run>& runs) {
  std::map<int, TableRow> rows;
  for (const auto& run : runs) {
    const std::string& name = run.run_name.function_name;
    const auto slash = name.find('/');
    if (run.error_occurred || slash == std::string::npos || run.iterations == 0) continue;
    TableRow& row = rows[std::stoi(name.substr(slash + 1))];
    row.n = std::stoi(name.substr(slash + 1));
    auto counter = [&](const char* key) {
      const auto it = run.counters.find(key);
      return it == run.counters.end() ? 0.0 : double(it->second);
    };
    row.walls = counter("walls"), row.openings = counter("openings");
    row.cells[name.substr(0, slash)] = {true,
                                        run.real_accumulated_time * 1e3 / double(run.iterations),
                                        counter("triangles"),
                                        counter("volume_error"),
                                        counter("bytes"),
                                        counter("build_ms")};
  }
  std::vector<TableRow> out;
  for (auto& [n, row] : rows) out.push_back(std::move(row));
  return out;
}

/// @return `value` formatted, or "" when the path did not run.
inline std::string cell(const TableRow& row, const char* path, double PathCell::*field,
                        const char* format) {
  const auto it = row.cells.find(path);
  if (it == row.cells.end() || !it->second.ran) return "";
  return fmt::format(fmt::runtime(format), it->second.*field);
}

/// @return the time of `path` over the fast path's, or "" if either did not run.
inline std::string ratio(const TableRow& row, const char* path) {
  const auto a = row.cells.find(path), f = row.cells.find("fast");
  if (a == row.cells.end() || f == row.cells.end() || f->second.ms <= 0.0) return "";
  return fmt::format("{:.0f}", a->second.ms / f->second.ms);
}

/// @return the row's fields in CSV column order (see bench/modeling_report.sh).
inline std::vector<std::string> row_fields(const TableRow& row) {
  std::vector<std::string> f{fmt::format("{}x{}", row.n, row.n), fmt::format("{}", row.walls),
                             fmt::format("{}", row.openings)};
  for (const char* p : kPaths) f.push_back(cell(row, p, &PathCell::ms, "{:.3f}"));
  for (const char* p : kPaths) f.push_back(cell(row, p, &PathCell::triangles, "{:.0f}"));
  for (const char* p : kPaths) f.push_back(cell(row, p, &PathCell::volume_error, "{:.2e}"));
  for (const char* p : {"cgal", "nef", "openscad"}) f.push_back(ratio(row, p));
  f.push_back(cell(row, "fast", &PathCell::bytes, "{:.0f}"));
  f.push_back(cell(row, "fast", &PathCell::build_ms, "{:.3f}"));
  return f;
}

inline const std::vector<std::string>& table_header() {
  static const std::vector<std::string> header{"scene",
                                               "walls",
                                               "openings",
                                               "fast_ms",
                                               "cgal_ms",
                                               "nef_ms",
                                               "openscad_ms",
                                               "fast_triangles",
                                               "cgal_triangles",
                                               "nef_triangles",
                                               "openscad_triangles",
                                               "fast_volume_error",
                                               "cgal_volume_error",
                                               "nef_volume_error",
                                               "openscad_volume_error",
                                               "cgal_over_fast",
                                               "nef_over_fast",
                                               "openscad_over_fast",
                                               "fast_off_bytes",
                                               "fast_build_ms"};
  return header;
}

inline std::string join(const std::vector<std::string>& fields, const char* sep) {
  std::string out;
  for (std::size_t i = 0; i < fields.size(); ++i) out += (i ? sep : "") + fields[i];
  return out;
}

inline std::string format_csv(const std::vector<TableRow>& rows) {
  std::string out = join(table_header(), ",") + "\n";
  for (const TableRow& row : rows) out += join(row_fields(row), ",") + "\n";
  return out;
}

inline std::string format_markdown(const std::vector<TableRow>& rows) {
  std::string out = "| " + join(table_header(), " | ") + " |\n|";
  for (std::size_t i = 0; i < table_header().size(); ++i) out += "---|";
  out += "\n";
  for (const TableRow& row : rows) out += "| " + join(row_fields(row), " | ") + " |\n";
  return out;
}

/// Writes the text atomically. @return false (with a message on stderr) on failure.
inline bool write_text(const std::string& path, const std::string& text) {
  const Status s = write_file_atomically(path, text);
  if (!s) std::fprintf(stderr, "build_bench: error: %s\n", s.message().c_str());
  return bool(s);
}

}  // namespace roomcad::bench
