#include "oracle/check/check.hpp"

#include <gmpxx.h>

#include <cmath>
#include <stdexcept>

#include "kernel/ids.hpp"

#include "oracle/check/check_impl.hpp"
#include "oracle/check/filtered_exact.hpp"

namespace dtlab {

const char* defect_name(DefectKind k) {
  switch (k) {
    case DefectKind::broken_adjacency: return "broken-adjacency";
    case DefectKind::inverted: return "inverted";
    case DefectKind::flat: return "flat";
    case DefectKind::non_delaunay: return "non-delaunay";
    case DefectKind::hull_not_convex: return "hull-not-convex";
    case DefectKind::overlap: return "overlap";
    case DefectKind::gap: return "gap";
    case DefectKind::missing_point: return "missing-point";
    case DefectKind::duplicate_vertex: return "duplicate-vertex";
    case DefectKind::euler: return "euler";
    case DefectKind::unproven: return "unproven";
  }
  return "?";
}

const char* span_name(AffineSpan s) {
  switch (s) {
    case AffineSpan::not_decided: return "not-decided";
    case AffineSpan::no_points: return "no-points";
    case AffineSpan::point: return "point";
    case AffineSpan::line: return "line";
    case AffineSpan::plane: return "plane";
    case AffineSpan::volume: return "volume";
  }
  return "?";
}

namespace check_detail {

std::vector<std::uint32_t> tet_vertices(const Tet& k) { return {k[0], k[1], k[2], k[3]}; }

void check_points(const Tetrahedralization& t, const std::vector<char>& used, std::span<const std::uint32_t> reported,
                  Collector& out, CheckStats& stats) {
  const auto& P = t.points;
  std::vector<char> is_reported(P.size(), 0);
  for (auto r : reported)
    if (r < P.size()) is_reported[r] = 1;
  std::vector<std::uint32_t> order(P.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return lex_less(P[a], P[b]) || (P[a] == P[b] && out.id(a) < out.id(b));
  });
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i + 1;
    while (j < order.size() && P[order[j]] == P[order[i]]) ++j;
    std::vector<std::uint32_t> vertices;
    for (std::size_t k = i; k < j; ++k)
      if (used[order[k]]) vertices.push_back(order[k]);
    if (vertices.size() >= 2)
      out.add(DefectKind::duplicate_vertex, {}, vertices, 0, "vertices with identical coordinates");
    if (vertices.empty()) {
      for (std::size_t k = i; k < j; ++k)
        out.add(DefectKind::missing_point, {}, {order[k]}, 0,
                is_reported[order[k]] ? "reported as a duplicate, but no vertex has its coordinates"
                                      : "input point is not a vertex");
    } else {
      stats.duplicates += (j - i) - vertices.size();
    }
    i = j;
  }
}

SpanWitness affine_span(std::span<const Point3> pts) {
  SpanWitness w;
  const std::size_t n = pts.size();
  if (n == 0) return w;
  w.span = AffineSpan::point;
  std::size_t b = 1;
  while (b < n && pts[b] == pts[0]) ++b;
  if (b == n) return w;
  w.span = AffineSpan::line;
  w.points[1] = static_cast<std::uint32_t>(b);
  const mpq_class ux = mpq_class(pts[b].x) - pts[0].x, uy = mpq_class(pts[b].y) - pts[0].y,
                  uz = mpq_class(pts[b].z) - pts[0].z;
  std::size_t c = 0;
  for (std::size_t i = b + 1; i < n && c == 0; ++i) {
    const mpq_class vx = mpq_class(pts[i].x) - pts[0].x, vy = mpq_class(pts[i].y) - pts[0].y,
                    vz = mpq_class(pts[i].z) - pts[0].z;
    if (uy * vz != uz * vy || uz * vx != ux * vz || ux * vy != uy * vx) c = i;
  }
  if (c == 0) return w;
  w.span = AffineSpan::plane;
  w.points[2] = static_cast<std::uint32_t>(c);
  const FilteredExact pred;
  for (std::size_t d = c + 1; d < n; ++d)
    if (pred.orient3d(pts[0], pts[b], pts[c], pts[d]) != 0) {
      w.span = AffineSpan::volume;
      w.points[3] = static_cast<std::uint32_t>(d);
      return w;
    }
  return w;
}

}  // namespace check_detail

namespace {

void require_finite(const Tetrahedralization& t) {
  for (const Point3& p : t.points)
    if (!is_finite(p)) throw std::invalid_argument("check: input has a non-finite coordinate");
}

// Renumbers t's vertices by first appearance in its tets (points in no tet follow, in
// their order) and moves the points to match; returns original[new id] = old id.
// Producers write tets in a spatially coherent order, so after this consecutive tets
// read nearby points and ranks: the checker's loads become mostly sequential.
std::vector<std::uint32_t> renumber_by_first_appearance(Tetrahedralization& t) {
  const std::size_t n = t.points.size();
  std::vector<std::uint32_t> rank = first_appearance(t.tets, n);
  std::uint32_t next = 0;
  for (auto r : rank)
    if (r != kNone) ++next;
  for (auto& r : rank)
    if (r == kNone) r = next++;
  for (Tet& k : t.tets)
    for (auto& v : k) v = rank[v];
  std::vector<std::uint32_t> original(n);
  for (std::size_t i = 0; i < n; ++i) original[rank[i]] = static_cast<std::uint32_t>(i);
  // points[new] = old points[original[new]], in place: follow each cycle once.
  std::vector<bool> moved(n, false);
  for (std::size_t start = 0; start < n; ++start) {
    if (moved[start]) continue;
    const Point3 first = t.points[start];
    std::size_t at = start;
    for (;;) {
      moved[at] = true;
      const std::size_t from = original[at];
      if (from == start) break;
      t.points[at] = t.points[from];
      at = from;
    }
    t.points[at] = first;
  }
  return original;
}

bool indices_in_range(const Tetrahedralization& t) {
  const std::size_t n = t.points.size();
  if (n >= (1u << 31) || t.tets.size() >= (1u << 30)) return false;
  for (const Tet& k : t.tets)
    for (auto v : k)
      if (v >= n) return false;
  return true;
}

}  // namespace

CheckReport check_tetrahedralization(const Tetrahedralization& t, const CheckOptions& options) {
  require_finite(t);
  return check_tetrahedralization_with(t, options, FilteredExact{});
}

CheckReport check_tetrahedralization(Tetrahedralization&& t, const CheckOptions& options) {
  require_finite(t);
  // Out-of-range ids are stage 1's to report, in the caller's numbering.
  if (!indices_in_range(t)) return check_tetrahedralization_with(t, options, FilteredExact{});
  const std::vector<std::uint32_t> original = renumber_by_first_appearance(t);
  std::vector<std::uint32_t> renamed;
  renamed.reserve(options.duplicates.size());
  // original is a permutation: its inverse maps a caller's id to ours.
  std::vector<std::uint32_t> ours(options.duplicates.empty() ? 0 : original.size());
  for (std::size_t i = 0; i < ours.size(); ++i) ours[original[i]] = static_cast<std::uint32_t>(i);
  for (auto d : options.duplicates) renamed.push_back(d < ours.size() ? ours[d] : d);
  CheckOptions o = options;
  o.duplicates = renamed;
  return check_tetrahedralization_with(t, o, FilteredExact{}, original);
}

}  // namespace dtlab
