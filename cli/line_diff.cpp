// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/line_diff.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace roomcad::cli {
namespace {

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    lines.push_back(text.substr(0, end));
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return lines;
}

enum class Op : std::uint8_t { keep, remove, add };

/// Edit script turning a into b, by longest common subsequence (or wholesale when too big).
std::vector<Op> edit_script(const std::vector<std::string_view>& a,
                            const std::vector<std::string_view>& b) {
  const std::size_t n = a.size();
  const std::size_t m = b.size();
  std::vector<Op> ops;
  if (n * m > 4'000'000) {
    ops.assign(n, Op::remove);
    ops.insert(ops.end(), m, Op::add);
    return ops;
  }
  // lcs[i][j]: longest common subsequence of a[i..] and b[j..].
  std::vector<std::uint32_t> lcs((n + 1) * (m + 1), 0);
  const auto at = [&](std::size_t i, std::size_t j) -> std::uint32_t& {
    return lcs[i * (m + 1) + j];
  };
  for (std::size_t i = n; i-- > 0;)
    for (std::size_t j = m; j-- > 0;)
      at(i, j) = a[i] == b[j] ? at(i + 1, j + 1) + 1 : std::max(at(i + 1, j), at(i, j + 1));
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < n || j < m) {
    if (i < n && j < m && a[i] == b[j]) {
      ops.push_back(Op::keep);
      ++i, ++j;
    } else if (j == m || (i < n && at(i + 1, j) >= at(i, j + 1))) {
      ops.push_back(Op::remove);
      ++i;
    } else {
      ops.push_back(Op::add);
      ++j;
    }
  }
  return ops;
}

}  // namespace

std::string diff_lines(std::string_view before, std::string_view after) {
  const std::vector<std::string_view> all_a = split_lines(before);
  const std::vector<std::string_view> all_b = split_lines(after);
  std::size_t head = 0;
  while (head < all_a.size() && head < all_b.size() && all_a[head] == all_b[head]) ++head;
  std::size_t tail = 0;
  while (tail + head < all_a.size() && tail + head < all_b.size() &&
         all_a[all_a.size() - 1 - tail] == all_b[all_b.size() - 1 - tail])
    ++tail;
  const std::vector<std::string_view> a(all_a.begin() + head, all_a.end() - tail);
  const std::vector<std::string_view> b(all_b.begin() + head, all_b.end() - tail);
  std::string out;
  std::size_t i = 0;
  std::size_t j = 0;
  bool in_change = false;
  for (const Op op : edit_script(a, b)) {
    if (op == Op::keep) {
      ++i, ++j;
      in_change = false;
      continue;
    }
    if (!in_change) out += fmt::format("@@ line {} @@\n", head + j + 1);
    in_change = true;
    if (op == Op::remove) out += fmt::format("- {}\n", a[i++]);
    else out += fmt::format("+ {}\n", b[j++]);
  }
  return out;
}

}  // namespace roomcad::cli
