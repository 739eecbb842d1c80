#pragma once
// A failure rate with its 95% confidence interval (Wilson score interval): the
// interval stays inside [0, 1] and is not degenerate at 0 or n failures, unlike
// the normal approximation. Used by campaign summaries and experiment reports.
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>

namespace dtlab::fuzz {

struct RateInterval {
  std::size_t failures = 0, cases = 0;
  double rate = 0, low = 0, high = 1;  // no cases: [0, 1]
};

inline RateInterval wilson_interval(std::size_t failures, std::size_t cases) {
  RateInterval r{failures, cases};
  if (cases == 0) return r;
  constexpr double z = 1.959963984540054;  // the 97.5% normal quantile
  const double n = static_cast<double>(cases);
  const double p = static_cast<double>(failures) / n;
  const double centre = p + z * z / (2 * n);
  const double spread = z * std::sqrt(p * (1 - p) / n + z * z / (4 * n * n));
  const double scale = 1 + z * z / n;
  r.rate = p;
  r.low = failures == 0 ? 0.0 : (centre - spread) / scale;
  r.high = failures == cases ? 1.0 : (centre + spread) / scale;
  return r;
}

// "12.5% [6.9, 21.6] (8/64)": the rate and interval in percent, and the counts.
inline std::string rate_text(const RateInterval& r) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.1f%% [%.1f, %.1f] (%zu/%zu)", 100 * r.rate, 100 * r.low, 100 * r.high,
                r.failures, r.cases);
  return buf;
}

}  // namespace dtlab::fuzz
