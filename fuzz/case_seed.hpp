#pragma once
// The seed of one fuzz case, derived from (campaign seed, family, case index) only,
// so a case is reproduced by those three values whatever the job count, the
// shard, or which other families and cases ran with it.
#include <cstdint>
#include <string_view>

#include "fuzz/rng.hpp"

namespace dtlab::fuzz {

constexpr std::uint64_t fnv1a(std::string_view s) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (char c : s) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return h;
}

constexpr std::uint64_t case_seed(std::uint64_t seed, std::string_view family, std::uint64_t index) {
  return mix64(mix64(mix64(seed) ^ fnv1a(family)) ^ index);
}

}  // namespace dtlab::fuzz
