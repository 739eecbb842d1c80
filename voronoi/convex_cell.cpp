#include "voronoi/convex_cell.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "kernel/ids.hpp"

namespace dtlab::vor {

namespace {
constexpr double kEps = 0x1p-52;
double max_abs(const Point3& p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}); }
double l1(const Point3& p) { return std::abs(p.x) + std::abs(p.y) + std::abs(p.z); }

// The same plane scaled by a power of two (exactly) to a largest normal component in
// [1, 2), so that the products of meet_error stay in range.
ClipPlane normalised(const ClipPlane& p) {
  const int e = std::ilogb(max_abs(p.n));
  return {{std::ldexp(p.n.x, -e), std::ldexp(p.n.y, -e), std::ldexp(p.n.z, -e)}, std::ldexp(p.c, -e)};
}
}  // namespace

// fl(n.x - c) is off by at most 2.5 eps |n|_1 |x|_inf + 0.5 eps |c| from n.x - c (eps =
// 2^-52, two products and sums, one subtraction), n from n* by eps/2 per component and
// c from c* by 2.5 eps |c| (a bisector's |n|^2 / 2; a wall's 0.5 eps |c|).
double plane_error(const ClipPlane& p, const Point3& x) { return 4 * kEps * (l1(p.n) * max_abs(x) + std::abs(p.c)); }

// With N the exact normals as rows and r* the exact residuals N x - c, x - x* = N^-1 r*,
// and column i of N^-1 is n_j x n_k / det N ((i, j, k) cyclic). Bounds in doubles: the
// residual by its value plus plane_error, each cross product by its value plus what
// rounding and the normals' error can change it by, det N from below likewise (each of
// its six terms within 4.5 eps of its value, their sum at most the product of the l1
// norms); the final factor covers rounding in the bound itself.
double meet_error(const ClipPlane& p, const ClipPlane& q, const ClipPlane& r, const Point3& x) {
  const ClipPlane pl[3] = {normalised(p), normalised(q), normalised(r)};
  const Point3 col[3] = {cross(pl[1].n, pl[2].n), cross(pl[2].n, pl[0].n), cross(pl[0].n, pl[1].n)};
  const double l[3] = {l1(pl[0].n), l1(pl[1].n), l1(pl[2].n)};
  const double det_lo = std::abs(dot(pl[0].n, col[0])) - 8 * kEps * l[0] * l[1] * l[2];
  if (!(det_lo > 0)) return INFINITY;
  double sum = 0;
  for (int i = 0; i < 3; ++i) {
    const double res = std::abs(dot(pl[i].n, x) - pl[i].c) + plane_error(pl[i], x);
    sum += res * (norm(col[i]) + 4 * kEps * l[(i + 1) % 3] * l[(i + 2) % 3]);
  }
  const double e = sum / det_lo * (1 + 32 * kEps);
  return e <= INFINITY ? e : INFINITY;  // NaN: no bound
}

namespace {
// side_error with |n| given: |n*| <= (1 + eps) |n|, and norm() rounds.
double side_error(const ClipPlane& p, double norm_n, const Point3& x, double err) {
  return (1 + 2 * kEps) * norm_n * err + plane_error(p, x);
}
}  // namespace

double side_error(const ClipPlane& p, const Point3& x, double err) { return side_error(p, norm(p.n), x, err); }

void ConvexCell::reset(const Box& b) {
  v_.clear();
  for (int k = 0; k < 8; ++k)
    v_.push_back({(k & 1) ? b.hi.x : b.lo.x, (k & 2) ? b.hi.y : b.lo.y, (k & 4) ? b.hi.z : b.lo.z});
  // Faces counter-clockwise seen from outside.
  static const std::uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                            {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  fv_.clear();
  fo_.assign(1, 0);
  face_tag_.clear();
  face_plane_.clear();
  planes_.clear();
  const double lo[3] = {b.lo.x, b.lo.y, b.lo.z}, hi[3] = {b.hi.x, b.hi.y, b.hi.z};
  for (int f = 0; f < 6; ++f) {
    fv_.insert(fv_.end(), quads[f], quads[f] + 4);
    fo_.push_back(static_cast<std::uint32_t>(fv_.size()));
    face_tag_.push_back(-1 - f);
    face_plane_.push_back(static_cast<std::uint32_t>(f));
    // Wall f: -x_k <= -lo_k or x_k <= hi_k, k = f / 2.
    const double sign = f % 2 ? 1 : -1;
    Point3 n{0, 0, 0};
    (f < 2 ? n.x : f < 4 ? n.y : n.z) = sign;
    planes_.push_back({n, f % 2 ? hi[f / 2] : -lo[f / 2]});
  }
  vs_.resize(8);
  for (std::uint32_t k = 0; k < 8; ++k) {
    const PlaneIds p = {k & 1, 2 + (k >> 1 & 1), 4 + (k >> 2 & 1)};
    vs_[k] = {meet_error(planes_[p[0]], planes_[p[1]], planes_[p[2]], v_[k]), p, kNone, {0, 0}, false};
  }
  ambiguous_ = false;
}

void ConvexCell::assign(std::span<const Point3> vertices, std::span<const std::uint32_t> face_offsets,
                        std::span<const std::uint32_t> face_vertices, std::span<const std::int32_t> tags,
                        const Point3& origin) {
  v_.clear();
  for (const auto& p : vertices) v_.push_back(p - origin);
  fo_.assign(face_offsets.begin(), face_offsets.end());
  fv_.assign(face_vertices.begin(), face_vertices.end());
  face_tag_.assign(tags.begin(), tags.end());
  face_plane_.assign(face_tag_.size(), kNone);
  planes_.clear();
  // The caller's band covers the vertices' own error (circumcentres).
  vs_.resize(v_.size());
  for (std::size_t k = 0; k < v_.size(); ++k)
    vs_[k] = {kEps * max_abs(v_[k]), {kNone, kNone, kNone}, kNone, {0, 0}, false};
  ambiguous_ = false;
}

void ConvexCell::clear() {
  v_.clear();
  vs_.clear();
  fv_.clear();
  fo_.assign(1, 0);
  face_tag_.clear();
  face_plane_.clear();
}

std::uint32_t ConvexCell::cut_vertex(std::uint32_t in, std::uint32_t out, std::size_t face) {
  const std::int32_t face_tag = face_tag_[face];
  const std::uint64_t key = (std::uint64_t(in) << 32) | out;
  for (std::size_t i = 0; i < cut_key_.size(); ++i)
    if (cut_key_[i] == key) {
      nvs_[cut_val_[i]].cut_tags.second = face_tag;
      nvs_[cut_val_[i]].planes[1] = face_plane_[face];
      return cut_val_[i];
    }
  // Interpolate from the inside end: the same edge seen from its two faces gives
  // the same point bit for bit.
  const double t = d_[in] / (d_[in] - d_[out]);
  const Point3 &a = v_[in], &b = v_[out];
  const Point3 p{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
  nv_.push_back(p);
  // An error e of the ends moves the crossing by e |b - a| |n| / |d_in - d_out| along
  // the edge: large when the edge meets the plane at a grazing angle (the bound where
  // the planes are unknown; bound_new_vertices replaces it where they are known).
  const double grow = norm(b - a) * norm_n_ / std::abs(d_[in] - d_[out]);
  const double err = std::max(vs_[in].err, vs_[out].err) * (1 + grow) + 4 * kEps * (max_abs(a) + max_abs(b));
  nvs_.push_back({err, {face_plane_[face], face_plane_[face], plane_}, kNone, {face_tag, face_tag}, true});
  const auto id = static_cast<std::uint32_t>(nv_.size() - 1);
  cut_key_.push_back(key);
  cut_val_.push_back(id);
  return id;
}

bool ConvexCell::clip(const Point3& n, double c, std::int32_t tag, double tol) {
  const std::size_t nv = v_.size();
  d_.resize(nv);
  side_.resize(nv);
  norm_n_ = norm(n);
  tol_ = tol;
  const double band = tol * norm_n_;
  const ClipPlane plane{n, c};
  bool doubt = false;
  for (std::size_t i = 0; i < nv; ++i) {
    const double d = dot(n, v_[i]) - c;
    d_[i] = d;
    side_[i] = d > band ? 1 : (d < -band ? -1 : 0);
    // Within the band, or so near that the vertex's own error or the plane's rounding
    // could flip the side.
    doubt |= std::abs(d) <= band + side_error(plane, norm_n_, v_[i], vs_[i].err);
  }
  ambiguous_ |= doubt;
  plane_ = static_cast<std::uint32_t>(planes_.size());
  planes_.push_back(plane);
  const bool cut = apply_sides(tag);
  if (!cut) planes_.pop_back();
  return cut;
}

bool ConvexCell::clip_signs(std::span<const signed char> side, std::int32_t tag) {
  side_.assign(side.begin(), side.end());
  d_.resize(side_.size());
  for (std::size_t i = 0; i < side_.size(); ++i) d_[i] = side_[i];  // cuts at midpoints
  norm_n_ = 0;
  tol_ = INFINITY;
  plane_ = kNone;
  return apply_sides(tag);
}

bool ConvexCell::apply_sides(std::int32_t tag) {
  const std::size_t nv = v_.size();
  bool any_out = false, any_in = false;
  for (std::size_t i = 0; i < nv; ++i) {
    any_out |= side_[i] > 0;
    any_in |= side_[i] <= 0;
  }
  if (!any_out) return false;
  if (!any_in) {
    clear();
    return true;
  }
  nv_.clear();
  nvs_.clear();
  remap_.resize(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    if (side_[i] <= 0) {
      remap_[i] = static_cast<std::uint32_t>(nv_.size());
      nv_.push_back(v_[i]);
      nvs_.push_back({vs_[i].err, vs_[i].planes, static_cast<std::uint32_t>(i), {0, 0}, side_[i] == 0});
    }
  }
  cut_key_.clear();
  cut_val_.clear();
  cap_from_.clear();
  cap_to_.clear();
  nfv_.clear();
  nfo_.assign(1, 0);
  nface_tag_.clear();
  nface_plane_.clear();
  const std::size_t nf = face_tag_.size();
  for (std::size_t f = 0; f < nf; ++f) {
    const std::uint32_t* fv = fv_.data() + fo_[f];
    const std::uint32_t m = fo_[f + 1] - fo_[f];
    bool cut = false, all_on = true;
    for (std::uint32_t k = 0; k < m; ++k) {
      cut |= side_[fv[k]] > 0;
      all_on &= side_[fv[k]] == 0;
    }
    // A face lying in the band is replaced by the new face (its neighbours' edges
    // on the plane chain that face's outline).
    if (all_on) continue;
    poly_.clear();
    if (!cut) {
      for (std::uint32_t k = 0; k < m; ++k) poly_.push_back(remap_[fv[k]]);
    } else {
      for (std::uint32_t k = 0; k < m; ++k) {
        const std::uint32_t a = fv[k], b = fv[(k + 1) % m];
        if (side_[a] <= 0) poly_.push_back(remap_[a]);
        if ((side_[a] < 0 && side_[b] > 0))
          poly_.push_back(cut_vertex(a, b, f));
        else if (side_[a] > 0 && side_[b] < 0)
          poly_.push_back(cut_vertex(b, a, f));
      }
      if (poly_.size() < 3) continue;
    }
    const std::size_t pm = poly_.size();
    for (std::size_t k = 0; k < pm; ++k) {
      const std::uint32_t a = poly_[k], b = poly_[(k + 1) % pm];
      if (nvs_[a].on && nvs_[b].on) {
        cap_from_.push_back(b);
        cap_to_.push_back(a);
      }
    }
    nfv_.insert(nfv_.end(), poly_.begin(), poly_.end());
    nfo_.push_back(static_cast<std::uint32_t>(nfv_.size()));
    nface_tag_.push_back(face_tag_[f]);
    nface_plane_.push_back(face_plane_[f]);
  }
  build_cap(tag);
  bound_new_vertices();
  // Drop vertices no face uses any more (kept "on" vertices of dropped faces).
  std::vector<std::uint32_t>& used = remap_;
  used.assign(nv_.size(), kNone);
  v_.clear();
  vs_.clear();
  for (auto& i : nfv_) {
    if (used[i] == kNone) {
      used[i] = static_cast<std::uint32_t>(v_.size());
      v_.push_back(nv_[i]);
      vs_.push_back(nvs_[i]);
    }
    i = used[i];
  }
  std::swap(fv_, nfv_);
  std::swap(fo_, nfo_);
  std::swap(face_tag_, nface_tag_);
  std::swap(face_plane_, nface_plane_);
  if (face_tag_.size() < 4) clear();
  return true;
}

// A new vertex whose three planes are known gets meet_error's bound instead of the
// compounded one; a vertex off by more than the band makes the cell ambiguous.
void ConvexCell::bound_new_vertices() {
  for (std::size_t v = 0; v < nv_.size(); ++v) {
    VertexState& s = nvs_[v];
    if (s.from != kNone) continue;
    const PlaneIds& p = s.planes;
    if (p[0] != kNone && p[1] != kNone && p[2] != kNone)
      s.err = meet_error(planes_[p[0]], planes_[p[1]], planes_[p[2]], nv_[v]);
    ambiguous_ |= s.err > tol_;
  }
}

// Chains the on-plane edges into the new face; falls back to sorting the on-plane
// vertices by angle if the chain is not one simple loop (only inside the band).
void ConvexCell::build_cap(std::int32_t tag) {
  cap_sorted_ = false;
  const std::size_t k = cap_from_.size();
  if (k < 3) return;
  poly_.clear();
  std::uint32_t cur = cap_from_[0];
  bool ok = true;
  for (std::size_t step = 0; step < k; ++step) {
    poly_.push_back(cur);
    std::size_t hits = 0, next = 0;
    for (std::size_t i = 0; i < k; ++i)
      if (cap_from_[i] == cur) ++hits, next = i;
    if (hits != 1) {
      ok = false;
      break;
    }
    cur = cap_to_[next];
    if (cur == cap_from_[0]) {
      ok = step + 1 == k;
      break;
    }
  }
  if (!ok || cur != cap_from_[0]) {
    cap_sorted_ = true;
    poly_.assign(cap_from_.begin(), cap_from_.end());
    std::sort(poly_.begin(), poly_.end());
    poly_.erase(std::unique(poly_.begin(), poly_.end()), poly_.end());
    if (poly_.size() < 3) return;
    Point3 c{0, 0, 0};
    for (auto i : poly_) c = c + nv_[i];
    c = 1.0 / poly_.size() * c;
    // The face normal from the loop edges (all of them orient the cap the same way).
    Point3 nrm{0, 0, 0};
    for (std::size_t i = 0; i < k; ++i) nrm = nrm + cross(nv_[cap_from_[i]] - c, nv_[cap_to_[i]] - c);
    Point3 u = nv_[poly_[0]] - c;
    Point3 w = cross(nrm, u);
    std::vector<std::pair<double, std::uint32_t>> ang;
    for (auto i : poly_) {
      const Point3 r = nv_[i] - c;
      ang.push_back({std::atan2(dot(r, w), dot(r, u) * norm(nrm)), i});
    }
    std::sort(ang.begin(), ang.end());
    for (std::size_t i = 0; i < ang.size(); ++i) poly_[i] = ang[i].second;
  }
  nfv_.insert(nfv_.end(), poly_.begin(), poly_.end());
  nfo_.push_back(static_cast<std::uint32_t>(nfv_.size()));
  nface_tag_.push_back(tag);
  nface_plane_.push_back(plane_);
}

double ConvexCell::volume() const {
  if (empty()) return 0;
  // Cones from vertex 0 over every face (signed, so any apex works; v0 keeps it local).
  const Point3 o = v_[0];
  double vol = 0;
  for (std::size_t f = 0; f < face_count(); ++f) {
    auto fv = face(f);
    const Point3 a = v_[fv[0]] - o;
    for (std::size_t k = 1; k + 1 < fv.size(); ++k) vol += det3(a, v_[fv[k]] - o, v_[fv[k + 1]] - o);
  }
  return vol / 6;
}

Point3 ConvexCell::centroid() const {
  if (empty()) return {0, 0, 0};
  const Point3 o = v_[0];
  double vol = 0;
  Point3 m{0, 0, 0};
  for (std::size_t f = 0; f < face_count(); ++f) {
    auto fv = face(f);
    const Point3 a = v_[fv[0]] - o;
    for (std::size_t k = 1; k + 1 < fv.size(); ++k) {
      const Point3 b = v_[fv[k]] - o, c = v_[fv[k + 1]] - o;
      const double w = det3(a, b, c);
      vol += w;
      m = m + w * (a + b + c);
    }
  }
  return o + 1.0 / (4 * vol) * m;
}

void ConvexCell::translate(const Point3& t) {
  for (auto& p : v_) p = p + t;
  for (std::size_t k = 0; k < v_.size(); ++k) vs_[k].err += kEps * max_abs(v_[k]);
}

}  // namespace dtlab::vor
