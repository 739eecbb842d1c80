#pragma once
// Insertion orders: the input order, or a biased randomized insertion order (BRIO,
// Amenta, Choi & Rote 2003) with each round sorted along a Hilbert curve, so that
// consecutive points are close (short walks) while the rounds keep the expected
// cost of randomized incremental construction.
#include <cstdint>
#include <span>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab {

// Hilbert index (3*bits bits) of a point with `bits`-bit integer coordinates, bits <= 21.
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits);

// A BRIO permutation of 0..n-1: random rounds [n/8^(k+1), n/8^k), the last (7/8 of
// the points) largest, each round Hilbert-sorted. `threads` > 1: the keys and the sort
// of the large rounds on threads (the same permutation).
std::vector<std::uint32_t> brio_order(std::span<const Point3> points, std::uint64_t seed, unsigned threads = 1);

// The rounds of brio_order for n points, first to last: positions [r[k], r[k+1]) of
// the order, r.front() == 0, r.back() == n.
std::vector<std::size_t> brio_rounds(std::size_t n);

}  // namespace dtlab
