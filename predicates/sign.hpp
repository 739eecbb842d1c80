#pragma once
// The sign of a predicate as a type. Backends (backend.hpp) and the plug-in C ABI
// return an int in {-1, 0, +1}; the kernel converts that int once, where it asks the
// backend (kernel/geometry.hpp), and decides on Sign from there on. A semi-static
// filter's answer is a FilterSign: a sign it could prove, or `undecided` (ask the full
// predicate) — its own value, never confused with a sign.
namespace dtlab {

enum class Sign : int { negative = -1, zero = 0, positive = 1 };

// s in {-1, 0, +1}, as every backend returns.
constexpr Sign to_sign(int s) { return static_cast<Sign>(s); }
constexpr int to_int(Sign s) { return static_cast<int>(s); }
constexpr Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }
constexpr Sign operator*(Sign a, Sign b) { return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b)); }

enum class FilterSign : int { negative = -1, zero = 0, positive = 1, undecided = 2 };

constexpr FilterSign filter_sign(double v) { return v > 0 ? FilterSign::positive : FilterSign::negative; }
constexpr bool decided(FilterSign s) { return s != FilterSign::undecided; }
// The sign a filter decided (precondition: decided(s)), and a sign as decided.
constexpr Sign to_sign(FilterSign s) { return static_cast<Sign>(static_cast<int>(s)); }
constexpr FilterSign to_filter_sign(Sign s) { return static_cast<FilterSign>(static_cast<int>(s)); }

}  // namespace dtlab
