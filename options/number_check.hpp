#pragma once
// The one check of a number given as text (an option's value, a factor inside one):
// a finite number, within a stated range, whole where a count is meant. Used by the
// CLI's validators (cli/number_options.hpp) and the Python module alike.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

namespace dtlab {

// "%g" of a range bound, as the messages show it.
inline std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Empty when `text` is a number in [lo, hi] (whole if `whole`), else the reason.
inline std::string check_number(const std::string& text, double lo, double hi, bool whole) {
  const char* b = text.data();
  const char* e = b + text.size();
  if (b != e && *b == '+') ++b;
  double v = 0;
  auto [p, ec] = std::from_chars(b, e, v);
  const std::string shown = text.size() <= 32 ? text : text.substr(0, 24) + "...";
  if (ec == std::errc::result_out_of_range) return "'" + shown + "' is out of range of a double";
  if (ec != std::errc() || p != e) return "'" + shown + "' is not a number";
  if (!std::isfinite(v)) return "'" + shown + "' is not finite";
  if (whole && v != std::trunc(v)) return "'" + shown + "' is not a whole number";
  if (v < lo || v > hi) return "'" + shown + "' is not in [" + number_text(lo) + ", " + number_text(hi) + "]";
  return {};
}

}  // namespace dtlab
