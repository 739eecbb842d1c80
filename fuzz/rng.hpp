#pragma once
// A reproducible random source for the generators. std::mt19937_64's output
// sequence is fixed by the standard, but the std:: distributions and std::shuffle
// are not, so every conversion used by dtlab is written here: same seed, same
// bits, on every platform and standard library. No libm call is involved.
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace dtlab::fuzz {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  std::uint64_t next() { return engine_(); }

  // Uniform on [0, 1): the top 53 bits scaled by 2^-53 (exact).
  double unit() { return static_cast<double>(next() >> 11) * 0x1p-53; }

  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }

  // Uniform on [0, n) without modulo bias (rejection on the top of the range); n > 0.
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
    for (;;) {
      const std::uint64_t v = next();
      if (v < limit) return v % n;
    }
  }

  // Uniform integer on [lo, hi], lo <= hi.
  std::int64_t range(std::int64_t lo, std::int64_t hi) {
    return lo + static_cast<std::int64_t>(below(static_cast<std::uint64_t>(hi - lo) + 1));
  }

  bool coin(double p) { return unit() < p; }

  // Roughly normal, mean 0, variance 1: Irwin-Hall sum of 12 uniforms minus 6
  // (avoids log/cos, whose last bits differ between libm implementations).
  double gaussianish() {
    double s = 0;
    for (int i = 0; i < 12; ++i) s += unit();
    return s - 6.0;
  }

  template <class T>
  void shuffle(std::vector<T>& v) {
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[below(i)]);
  }

 private:
  std::mt19937_64 engine_;
};

// SplitMix64 finaliser: a bijective 64-bit mix used to derive independent seeds.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace dtlab::fuzz
