#include "oracle/peers/peer_adapter.hpp"

#include <cstring>
#include <unordered_map>
#include <utility>

#include "kernel/ids.hpp"
#include "oracle/check/filtered_exact.hpp"

namespace dtlab {
namespace {

struct CoordHash {
  std::size_t operator()(const Point3& p) const {
    const auto bits = [](double v) {
      std::uint64_t b;
      v = v == 0 ? 0.0 : v;  // -0 and +0 are one coordinate
      std::memcpy(&b, &v, sizeof b);
      return b;
    };
    std::uint64_t h = bits(p.x) * 0x9E3779B97F4A7C15ull;
    h ^= bits(p.y) + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
    h ^= bits(p.z) + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h);
  }
};
struct CoordEq {
  bool operator()(const Point3& a, const Point3& b) const { return a.x == b.x && a.y == b.y && a.z == b.z; }
};

}  // namespace

void normalise_answer(std::span<const Point3> points, const PeerAnswer& answer, PeerOrientation orientation,
                      PeerRun& run) {
  const std::size_t n = points.size();
  std::unordered_map<Point3, std::uint32_t, CoordHash, CoordEq> first;
  first.reserve(n);
  std::vector<std::uint32_t> canon(n + answer.extra.size());
  for (std::size_t i = 0; i < n; ++i)
    canon[i] = first.try_emplace(points[i], static_cast<std::uint32_t>(i)).first->second;
  for (std::size_t j = 0; j < answer.extra.size(); ++j) {
    const auto it = first.find(answer.extra[j]);
    canon[n + j] = it == first.end() ? kNone : it->second;
  }
  std::vector<char> extra_used(answer.extra.size(), 0);
  Tetrahedralization t;
  t.points.assign(points.begin(), points.end());
  t.tets.reserve(answer.tets.size());
  const FilteredExact exact;
  for (const Tet& raw : answer.tets) {
    Tet k;
    bool extra = false;
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t v = raw[i];
      if (v >= canon.size() || canon[v] == kNone) {
        extra = true;
        if (v >= n && v < canon.size()) extra_used[v - n] = 1;
        k[i] = v;
      } else {
        k[i] = canon[v];
      }
    }
    if (extra) {
      ++run.extra_tets;
      continue;
    }
    const bool raw_distinct = raw[0] != raw[1] && raw[0] != raw[2] && raw[0] != raw[3] && raw[1] != raw[2] &&
                              raw[1] != raw[3] && raw[2] != raw[3];
    const bool distinct = k[0] != k[1] && k[0] != k[2] && k[0] != k[3] && k[1] != k[2] && k[1] != k[3] && k[2] != k[3];
    if (raw_distinct && !distinct) {
      ++run.collapsed_tets;
      continue;
    }
    if (orientation == PeerOrientation::swapped)
      std::swap(k[0], k[1]);
    else if (orientation == PeerOrientation::by_sign && distinct &&
             exact.orient3d(points[k[0]], points[k[1]], points[k[2]], points[k[3]]) < 0)
      std::swap(k[0], k[1]);
    t.tets.push_back(k);
  }
  for (char u : extra_used) run.extra_vertices += u;
  std::vector<char> used(n, 0);
  for (const Tet& k : t.tets)
    for (auto v : k)
      if (v < n) used[v] = 1;
  for (std::size_t i = 0; i < n; ++i)
    if (!used[i]) run.unused.push_back(static_cast<std::uint32_t>(i));
  run.mesh = std::move(t);
}

void judge_answer(PeerRun& run, unsigned threads) {
  if (!run.mesh) return;
  CheckOptions co;
  co.duplicates = run.unused;
  co.threads = threads;
  run.report = check_tetrahedralization(*run.mesh, co);
  run.verdict = run.extra_tets ? Verdict::extra_points : verdict_of(*run.report);
}

void adapt_and_judge(std::span<const Point3> points, const PeerAnswer& answer, PeerOrientation orientation, bool check,
                     unsigned threads, PeerRun& run) {
  normalise_answer(points, answer, orientation, run);
  if (check) judge_answer(run, threads);
}

}  // namespace dtlab
