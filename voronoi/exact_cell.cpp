#include "voronoi/exact_cell.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "kernel/ids.hpp"

namespace dtlab::vor {

namespace {

// a.y <= c in the scaled frame y = 2^-e (x - s), as the row (a, -c).
using Plane = std::array<mpz_class, 4>;
// The point (h0, h1, h2) / h3, h3 > 0.
using Hom = std::array<mpz_class, 4>;

// The exponent of the lowest bit of a nonzero double.
int low_bit(double x) {
  int ex = 0;
  std::frexp(x, &ex);
  return ex - 53;
}

// x * 2^-e as an integer (exact: e is at most the lowest bit of x).
void to_integer(mpz_class& out, double x, int e) {
  if (x == 0) {
    out = 0;
    return;
  }
  int ex = 0;
  out = std::ldexp(std::frexp(x, &ex), 53);  // |m| < 2^53, exact
  mpz_mul_2exp(out.get_mpz_t(), out.get_mpz_t(), static_cast<mp_bitcnt_t>(ex - 53 - e));
}

struct Frame {
  int e = 0;       // scale: integer = double * 2^-e
  mpz_class s[3];  // the site, scaled
  mpz_class tmp;

  void point(const Point3& p, mpz_class out[3]) {
    to_integer(out[0], p.x, e);
    to_integer(out[1], p.y, e);
    to_integer(out[2], p.z, e);
  }
};

// The determinant of rows r0, r1, r2 restricted to columns c0 < c1 < c2.
void minor3(mpz_class& out, const Plane& r0, const Plane& r1, const Plane& r2, int c0, int c1, int c2, mpz_class& t) {
  out = r0[c0] * (r1[c1] * r2[c2] - r1[c2] * r2[c1]);
  t = r0[c1] * (r1[c0] * r2[c2] - r1[c2] * r2[c0]);
  out -= t;
  t = r0[c2] * (r1[c0] * r2[c1] - r1[c1] * r2[c0]);
  out += t;
}

// The common point of three planes: h_j = (-1)^j det(rows without column j), so that
// every row r has r.h = 0 (a determinant with a repeated row); normalised to h3 > 0.
bool meet(Hom& h, const Plane& p, const Plane& q, const Plane& r, mpz_class& t) {
  minor3(h[0], p, q, r, 1, 2, 3, t);
  minor3(h[1], p, q, r, 0, 2, 3, t);
  minor3(h[2], p, q, r, 0, 1, 3, t);
  minor3(h[3], p, q, r, 0, 1, 2, t);
  h[1] = -h[1];
  h[3] = -h[3];
  if (sgn(h[3]) == 0) return false;
  if (sgn(h[3]) < 0)
    for (auto& x : h) x = -x;
  return true;
}

int side(const Plane& p, const Hom& h, mpz_class& t) {
  t = p[0] * h[0];
  t += p[1] * h[1];
  t += p[2] * h[2];
  t += p[3] * h[3];
  return sgn(t);
}

// The vertex in doubles, relative to the site (within an ulp: one rounding).
Point3 to_point(const Hom& h, int e) {
  double c[3];
  for (int k = 0; k < 3; ++k) {
    mpq_class q(h[k], h[3]);
    q.canonicalize();
    if (e < 0)
      mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
    else
      mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
    c[k] = q.get_d();
  }
  return {c[0], c[1], c[2]};
}

// Per-thread state: planes by face tag, vertices, and scratch integers.
struct ExactState {
  Frame frame;
  std::vector<std::pair<std::int32_t, Plane>> planes;
  std::vector<Hom> h, nh;
  std::vector<signed char> sides;
  mpz_class t;

  const Plane& plane(std::int32_t tag) const {
    for (const auto& p : planes)
      if (p.first == tag) return p.second;
    throw std::logic_error("exact cell: no plane for a face");
  }
};

int lowest_bit(std::span<const Point3> sites, std::uint32_t i, std::span<const std::uint32_t> neighbors,
               const Box& box) {
  int e = 0;
  bool any = false;
  auto see = [&](const Point3& p) {
    for (double x : {p.x, p.y, p.z})
      if (x != 0) e = any ? std::min(e, low_bit(x)) : low_bit(x), any = true;
  };
  see(sites[i]);
  see(box.lo);
  see(box.hi);
  for (auto j : neighbors) see(sites[j]);
  return e;
}

// The six walls (tags -1..-6: x-lo, x-hi, y-lo, ...) and the box corners, vertex k of
// ConvexCell::reset at (k & 1 ? hi : lo, k & 2 ..., k & 4 ...).
void box_planes(ExactState& st, const Box& box) {
  Frame& f = st.frame;
  mpz_class lo[3], hi[3];
  f.point(box.lo, lo);
  f.point(box.hi, hi);
  st.planes.clear();
  for (int k = 0; k < 3; ++k) {
    Plane pl, ph;
    for (int j = 0; j < 3; ++j) pl[j] = ph[j] = 0;
    pl[k] = -1;  // -y_k <= -(lo_k - s_k)
    pl[3] = lo[k] - f.s[k];
    ph[k] = 1;  // y_k <= hi_k - s_k
    ph[3] = f.s[k] - hi[k];
    st.planes.push_back({-1 - 2 * k, pl});
    st.planes.push_back({-2 - 2 * k, ph});
  }
  st.h.resize(8);
  for (int k = 0; k < 8; ++k) {
    Hom& h = st.h[k];
    for (int j = 0; j < 3; ++j) h[j] = ((k >> j) & 1 ? hi[j] : lo[j]) - f.s[j];
    h[3] = 1;
  }
}

// 2u.y <= |u|^2, u = p - s.
Plane bisector(ExactState& st, const Point3& p) {
  mpz_class q[3];
  st.frame.point(p, q);
  Plane pl;
  pl[3] = 0;
  for (int k = 0; k < 3; ++k) {
    q[k] -= st.frame.s[k];
    pl[k] = 2 * q[k];
    pl[3] -= q[k] * q[k];
  }
  return pl;
}

// After a clip that cut: kept vertices keep their point, new ones meet the clip plane
// and the two faces of their edge.
void update_vertices(ExactState& st, ConvexCell& cell, const Plane& clip_plane, std::uint32_t site) {
  st.nh.resize(cell.vertex_count());
  for (std::size_t v = 0; v < cell.vertex_count(); ++v) {
    if (const std::uint32_t from = cell.kept_from(v); from != kNone) {
      std::swap(st.nh[v], st.h[from]);  // a kept vertex appears once
    } else {
      const auto [fa, fb] = cell.cut_faces(v);
      if (fa == fb || !meet(st.nh[v], st.plane(fa), st.plane(fb), clip_plane, st.t))
        throw std::runtime_error("voronoi: the exact cell of site " + std::to_string(site) +
                                 " has a vertex on parallel planes");
    }
    cell.set_vertex(v, to_point(st.nh[v], st.frame.e));
  }
  std::swap(st.h, st.nh);
}

}  // namespace

void exact_clip_cell(ConvexCell& cell, std::span<const Point3> sites, std::uint32_t i,
                     std::span<const std::uint32_t> neighbors, const Box& box) {
  thread_local ExactState st;
  const Point3 s = sites[i];
  st.frame.e = lowest_bit(sites, i, neighbors, box);
  st.frame.point(s, st.frame.s);
  cell.reset({box.lo - s, box.hi - s});
  box_planes(st, box);
  for (std::size_t k = 0; k < st.h.size(); ++k) cell.set_vertex(k, to_point(st.h[k], st.frame.e));
  for (auto j : neighbors) {
    Plane p = bisector(st, sites[j]);
    st.sides.resize(st.h.size());
    for (std::size_t v = 0; v < st.h.size(); ++v) st.sides[v] = static_cast<signed char>(side(p, st.h[v], st.t));
    if (!cell.clip_signs(st.sides, static_cast<std::int32_t>(j))) continue;
    if (cell.empty()) break;
    if (cell.cap_sorted())
      throw std::runtime_error("voronoi: the exact cell of site " + std::to_string(i) + " has an open face");
    st.planes.push_back({static_cast<std::int32_t>(j), std::move(p)});
    update_vertices(st, cell, st.planes.back().second, i);
  }
}

}  // namespace dtlab::vor
