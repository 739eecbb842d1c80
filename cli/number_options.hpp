#pragma once
// Validators for every numeric command-line option: the value must be a finite number
// (no nan, inf or 1e999) within a stated range, and whole where a count is meant.
// A violation is a CLI11 validation error, so exit code 2 with a one-line message.
// Usage: sub->add_option("--margin", m)->check(number_in(0, 100)), and for counts
// ->transform(count_in(1, 1e9)) (a transform, so "1e5" reaches the integer as 100000).
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>

#include "options/number_check.hpp"

namespace dtlab::cli {

namespace number_options_detail {

using dtlab::check_number;  // options/number_check.hpp, shared with the Python module
inline std::string fmt(double v) { return number_text(v); }

}  // namespace number_options_detail

// A finite real number in [lo, hi].
inline CLI::Validator number_in(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& s) { return number_options_detail::check_number(s, lo, hi, false); },
      "NUMBER in [" + number_options_detail::fmt(lo) + ", " + number_options_detail::fmt(hi) + "]");
}

// A whole number in [lo, hi] (counts, sizes, thread numbers, seconds of budget). The
// same syntax as every other number ("1e5" is 100000): the text is rewritten in
// digits, so an integer option accepts it.
inline CLI::Validator count_in(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& s) {
        std::string why = number_options_detail::check_number(s, lo, hi, true);
        if (why.empty()) {
          double v = 0;
          const char* b = s.data() + (!s.empty() && s[0] == '+');
          std::from_chars(b, s.data() + s.size(), v);
          char buf[32];
          std::snprintf(buf, sizeof buf, "%.0f", v);
          s = buf;
        }
        return why;
      },
      "INTEGER in [" + number_options_detail::fmt(lo) + ", " + number_options_detail::fmt(hi) + "]");
}

// A 64-bit seed: an integer in [0, 2^64-1] written in digits. "-1", "2^64" and "1e23"
// are refused instead of wrapping to 2^64-1.
inline CLI::Validator seed_value() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        const char* b = s.data() + (!s.empty() && s[0] == '+');
        const char* e = s.data() + s.size();
        unsigned long long v = 0;
        auto [p, ec] = std::from_chars(b, e, v);
        const std::string shown = s.size() <= 32 ? s : s.substr(0, 24) + "...";
        if (b == e || ec != std::errc() || p != e)
          return "'" + shown + "' is not a seed (an integer in [0, 18446744073709551615], in digits)";
        return {};
      },
      "INTEGER in [0, 2^64-1]");
}

}  // namespace dtlab::cli
