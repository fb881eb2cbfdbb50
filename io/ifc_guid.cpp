// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/ifc_guid.h"

#include <cstdint>

#include <fmt/format.h>

namespace roomcad {
namespace {

/// The 64-bit FNV-1a hash of `text`, from `basis`, finished by SplitMix64's mixer.
std::uint64_t hash64(std::string_view text, std::uint64_t basis) {
  std::uint64_t h = basis;
  for (const char c : text) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
  return h ^ (h >> 31);
}

unsigned __int128 hash128(std::string_view key) {
  return (static_cast<unsigned __int128>(hash64(key, 0xcbf29ce484222325ULL)) << 64) |
         hash64(key, 0x84222325cbf29ce4ULL);
}

}  // namespace

std::string ifc_global_id(std::string_view key) {
  static constexpr char kDigits[] =
      "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_$";
  unsigned __int128 bits = hash128(key);
  std::string id(22, '0');
  for (int k = 21; k >= 1; --k, bits >>= 6) id[static_cast<std::size_t>(k)] = kDigits[bits & 63];
  id[0] = kDigits[bits & 3];
  return id;
}

std::optional<std::string> ifc_global_id_of(const Plan& plan, std::string_view id) {
  for (const Wall& w : plan.walls)
    if (w.id == id) return ifc_global_id(fmt::format("wall:{}", id));
  for (const Opening& o : plan.openings)
    if (o.id == id) return ifc_global_id(fmt::format("{}:{}", to_string(o.type), id));
  for (const Slab& s : plan.slabs)
    if (s.id == id) return ifc_global_id(fmt::format("slab:{}", id));
  return std::nullopt;
}

std::string hashed_guid(std::string_view key) {
  const unsigned __int128 bits = hash128(key);
  const auto hi = static_cast<std::uint64_t>(bits >> 64), lo = static_cast<std::uint64_t>(bits);
  return fmt::format("{:08x}-{:04x}-{:04x}-{:04x}-{:012x}", hi >> 32, (hi >> 16) & 0xffff,
                     hi & 0xffff, lo >> 48, lo & 0xffffffffffffULL);
}

}  // namespace roomcad
