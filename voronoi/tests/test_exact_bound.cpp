// The error bounds that decide when a double clip is trusted (meet_error, side_error)
// against GMP rationals, on near-degenerate planes; and whole cells: where the double
// clip is not ambiguous, it is the exact clip (voronoi/exact_cell.hpp) vertex for vertex.
#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "voronoi/convex_cell.hpp"
#include "voronoi/exact_cell.hpp"

using namespace dtlab;
using namespace dtlab::vor;

namespace {

using Q = mpq_class;
using QVec = std::array<Q, 3>;

// The exact plane n.y <= c, y relative to the site, next to its double ClipPlane.
struct TestPlane {
  QVec n;
  Q c;
  ClipPlane d;
};

QVec exact(const Point3& p) { return {Q(p.x), Q(p.y), Q(p.z)}; }
Q qdot(const QVec& a, const QVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
QVec qcross(const QVec& a, const QVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The bisector of s and p as compute_cell makes it.
TestPlane bisector(const Point3& s, const Point3& p) {
  const QVec qs = exact(s), qp = exact(p);
  const QVec u{qp[0] - qs[0], qp[1] - qs[1], qp[2] - qs[2]};
  const Point3 n = p - s;
  return {u, qdot(u, u) / 2, {n, 0.5 * dot(n, n)}};
}

// The wall x_axis <= w (hi) or x_axis >= w, moved by s, as ConvexCell::reset makes it.
TestPlane wall(int axis, bool hi, double w, const Point3& s) {
  const double sign = hi ? 1 : -1;
  TestPlane t{{Q(0), Q(0), Q(0)}, Q(sign) * (Q(w) - Q(coord(s, axis))), {}};
  t.n[axis] = sign;
  Point3 n{0, 0, 0};
  (axis == 0 ? n.x : axis == 1 ? n.y : n.z) = sign;
  t.d = {n, sign * (w - coord(s, axis))};
  return t;
}

// The exact meet of three planes (Cramer); false if they do not meet in a point.
bool exact_meet(const TestPlane& a, const TestPlane& b, const TestPlane& c, QVec& x) {
  const QVec c0 = qcross(b.n, c.n), c1 = qcross(c.n, a.n), c2 = qcross(a.n, b.n);
  const Q det = qdot(a.n, c0);
  if (sgn(det) == 0) return false;
  for (int k = 0; k < 3; ++k) x[k] = (a.c * c0[k] + b.c * c1[k] + c.c * c2[k]) / det;
  return true;
}

// The same meet in doubles, as a cell would have it (a few roundings off).
Point3 double_meet(const ClipPlane& a, const ClipPlane& b, const ClipPlane& c) {
  const Point3 c0 = cross(b.n, c.n), c1 = cross(c.n, a.n), c2 = cross(a.n, b.n);
  return 1.0 / dot(a.n, c0) * (a.c * c0 + b.c * c1 + c.c * c2);
}

// |x - y| <= bound, exactly.
bool within(const Point3& x, const QVec& y, double bound) {
  const QVec qx = exact(x);
  const QVec d{qx[0] - y[0], qx[1] - y[1], qx[2] - y[2]};
  return qdot(d, d) <= Q(bound) * Q(bound);
}

struct Rng {
  std::mt19937_64 g;
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(g); }
  double log_uniform(double lo_exp, double hi_exp) { return std::pow(10.0, uniform(lo_exp, hi_exp)); }
  Point3 direction() {
    const Point3 p{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
    return 1.0 / norm(p) * p;
  }
  // Each coordinate nudged by a relative amount between 1e-17 and 1e-9 (0 at times).
  Point3 jitter(const Point3& p) {
    auto j = [&](double x) { return g() % 4 == 0 ? x : x * (1 + log_uniform(-17, -9) * uniform(-1, 1)); };
    return {j(p.x), j(p.y), j(p.z)};
  }
};

// A plane of a random cell of site s: a wall of [-0.5, 1.5]^3 at times, else the
// bisector with a site at a distance from 1e-12 to 1.
TestPlane random_plane(Rng& r, const Point3& s) {
  if (r.g() % 4 == 0) {
    const bool hi = r.g() % 2;
    return wall(static_cast<int>(r.g() % 3), hi, hi ? 1.5 : -0.5, s);
  }
  return bisector(s, s + r.log_uniform(-12, 0) * r.direction());
}

}  // namespace

TEST_CASE("meet_error bounds the distance to the exact meet; side_error certifies exact sides", "[voronoi][exact]") {
  Rng r{std::mt19937_64(27)};
  int bounded = 0, answered = 0, unanswered = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Point3 s{r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1)};
    const TestPlane p[3] = {random_plane(r, s), random_plane(r, s), random_plane(r, s)};
    QVec xs;
    if (!exact_meet(p[0], p[1], p[2], xs)) continue;
    const Point3 x = double_meet(p[0].d, p[1].d, p[2].d);
    const double e = meet_error(p[0].d, p[1].d, p[2].d, x);
    if (!std::isfinite(e)) continue;
    ++bounded;
    INFO("trial " << trial << " bound " << e);
    REQUIRE(within(x, xs, e));
    // A fourth site near the sphere through s about the vertex: its bisector passes
    // within ~|jitter| of the vertex, either side.
    const double radius = norm(x);
    if (!(radius > 0 && radius < 10)) continue;
    const TestPlane q = bisector(s, r.jitter(s + x + radius * r.direction()));
    const double d = dot(q.d.n, x) - q.d.c;
    if (std::abs(d) <= side_error(q.d, x, e)) {
      ++unanswered;
      continue;
    }
    ++answered;
    REQUIRE((d > 0 ? 1 : -1) == sgn(qdot(q.n, xs) - q.c));
  }
  INFO("bounded " << bounded << " answered " << answered << " unanswered " << unanswered);
  CHECK(bounded > 2000);
  CHECK(answered > 500);
  CHECK(unanswered > 50);
}

namespace {

// A site with 3-6 others cospherical with it up to a jitter (their bisectors nearly meet
// in one point), at times in close pairs, and 12 more around it.
std::vector<Point3> near_degenerate_sites(Rng& r) {
  const Point3 s{r.uniform(0.2, 0.8), r.uniform(0.2, 0.8), r.uniform(0.2, 0.8)};
  const Point3 centre = s + r.uniform(0.01, 0.3) * r.direction();
  const double radius = norm(s - centre);
  std::vector<Point3> sites{s};
  const int n = 3 + static_cast<int>(r.g() % 4);
  for (int k = 0; k < n; ++k) {
    const Point3 p = r.jitter(centre + radius * r.direction());
    sites.push_back(p);
    if (r.g() % 8 == 0) sites.push_back(p + r.log_uniform(-13, -9) * r.direction());
  }
  for (int k = 0; k < 12; ++k) sites.push_back(s + r.uniform(0.05, 0.4) * r.direction());
  return sites;
}

}  // namespace

TEST_CASE("a double clip that is not ambiguous is the exact clip", "[voronoi][exact]") {
  Rng r{std::mt19937_64(2027)};
  const Box box{{0, 0, 0}, {1, 1, 1}};
  int trusted = 0, flagged = 0;
  ConvexCell cell, exact_cell;
  for (int trial = 0; trial < 1500; ++trial) {
    const std::vector<Point3> sites = near_degenerate_sites(r);
    std::vector<std::uint32_t> neighbors;
    for (std::uint32_t j = 1; j < sites.size(); ++j) neighbors.push_back(j);
    // The band from none to compute_cell's usual 1e-12 of the diagonal.
    const double band = trial % 3 == 0 ? 0 : r.log_uniform(-16, -12) * box.diagonal();
    const Point3 s = sites[0];
    cell.reset({box.lo - s, box.hi - s});
    for (auto j : neighbors) {
      const Point3 n = sites[j] - s;
      cell.clip(n, 0.5 * dot(n, n), static_cast<std::int32_t>(j), band);
      if (cell.empty()) break;
    }
    if (cell.ambiguous()) {
      ++flagged;
      continue;
    }
    ++trusted;
    INFO("trial " << trial);
    exact_clip_cell(exact_cell, sites, 0, neighbors, box);
    REQUIRE(cell.face_count() == exact_cell.face_count());
    CHECK(std::equal(cell.face_tags().begin(), cell.face_tags().end(), exact_cell.face_tags().begin()));
    CHECK(std::equal(cell.face_offsets().begin(), cell.face_offsets().end(), exact_cell.face_offsets().begin()));
    CHECK(std::equal(cell.face_vertices().begin(), cell.face_vertices().end(), exact_cell.face_vertices().begin()));
    REQUIRE(cell.vertex_count() == exact_cell.vertex_count());
    // The exact vertices are rounded once (half an ulp of a coordinate below 2).
    for (std::size_t v = 0; v < cell.vertex_count(); ++v)
      CHECK(norm(cell.vertices()[v] - exact_cell.vertices()[v]) <= cell.vertex_error(v) + 0x1p-52);
  }
  INFO("trusted " << trusted << " flagged " << flagged);
  CHECK(trusted > 200);
  CHECK(flagged > 100);
}
