#include "voronoi/dual_cell.hpp"

#include <algorithm>
#include <cmath>

#include "kernel/ids.hpp"

namespace dtlab::vor {

namespace {
// The face opposite position i of a positively oriented tet, ordered so that
// (face, v) is an even permutation of the tet: every link triangle of v then has the
// same orientation as seen from v.
constexpr int kLink[4][3] = {{2, 1, 3}, {0, 2, 3}, {1, 0, 3}, {0, 1, 2}};

double dist2(const Point3& a, const Point3& b) {
  const Point3 d = a - b;
  return dot(d, d);
}
}  // namespace

bool DualCellBuilder::gather(std::uint32_t v, std::span<const std::uint32_t> star, std::span<const Tet> tets,
                             std::span<const char> bad) {
  for (auto g : global_) local_[g] = kNone;
  global_.clear();
  tri_.resize(3 * star.size());
  std::uint32_t* tri = tri_.data();
  bool ok = true;
  for (auto t : star) {
    if (prefetch_) __builtin_prefetch(prefetch_ + t);
    const Tet& q = tets[t];
    const int i = q[0] == v ? 0 : q[1] == v ? 1 : q[2] == v ? 2 : 3;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t g = q[kLink[i][k]];
      if (local_[g] == kNone) {
        local_[g] = static_cast<std::uint32_t>(global_.size());
        global_.push_back(g);
      }
      *tri++ = local_[g];
    }
    ok &= !bad[t];
  }
  return ok;
}

std::uint32_t DualCellBuilder::find(std::uint32_t t) {
  while (parent_[t] != t) t = parent_[t] = parent_[parent_[t]];
  return t;
}

bool DualCellBuilder::link_rings(std::size_t nl, std::size_t nt) {
  coff_.assign(nl + 1, 0);
  for (auto a : tri_) ++coff_[a + 1];
  for (std::size_t a = 0; a < nl; ++a) coff_[a + 1] += coff_[a];
  // Corners bucketed by link vertex: (triangle, vertex after, vertex before).
  bnext_.resize(tri_.size());
  bprev_.resize(tri_.size());
  btri_.resize(tri_.size());
  ring_.assign(coff_.begin(), coff_.end() - 1);  // fill pointers
  for (std::uint32_t t = 0; t < nt; ++t) {
    const std::uint32_t x[3] = {tri_[3 * t], tri_[3 * t + 1], tri_[3 * t + 2]};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t pos = ring_[x[k]]++;
      btri_[pos] = t;
      bnext_[pos] = x[(k + 1) % 3];
      bprev_[pos] = x[(k + 2) % 3];
    }
  }
  // Rings: around link vertex a, from the triangle (a, p, q) to the one (a, y, p).
  ring_.clear();
  roff_.assign(1, 0);
  if (by_prev_.size() < nl) by_prev_.resize(nl, 0);
  for (std::uint32_t a = 0; a < nl; ++a) {
    const std::uint32_t b = coff_[a], e = coff_[a + 1];
    // by_prev_[x]: the corner of a whose previous vertex is x (stale entries from other
    // link vertices are caught by the range and value checks, so no reset is needed).
    for (std::uint32_t k = b; k < e; ++k) by_prev_[bprev_[k]] = k;
    std::uint32_t cur = b;
    for (std::uint32_t step = 0;; ++step) {
      if (step == e - b) return false;  // not one cycle
      ring_.push_back(btri_[cur]);
      const std::uint32_t target = bnext_[cur];
      const std::uint32_t nxt = by_prev_[target];
      if (nxt < b || nxt >= e || bprev_[nxt] != target) return false;  // open link: a hull site
      if (nxt == b) {
        if (step + 1 != e - b) return false;
        break;
      }
      cur = nxt;
    }
    roff_.push_back(static_cast<std::uint32_t>(ring_.size()));
  }
  return true;
}

DualCellBuilder::Merge DualCellBuilder::merge_close_centres(std::size_t nl, std::size_t nt, const Point3* c,
                                                            double band, double min_edge) {
  const double band2 = band * band, min2 = min_edge * min_edge;
  bool merged = false;
  double shortest = INFINITY;
  for (std::uint32_t a = 0; a < nl; ++a) {
    const std::uint32_t b = roff_[a], e = roff_[a + 1];
    if (e - b < 3) return Merge::failed;
    for (auto k = b; k < e; ++k) {
      const std::uint32_t s = ring_[k], t = ring_[k + 1 < e ? k + 1 : b];
      const double d = dist2(c[s], c[t]);
      shortest = std::min(shortest, d);
      if (d <= band2) {
        if (!merged) {
          parent_.resize(nt);
          for (std::uint32_t x = 0; x < nt; ++x) parent_[x] = x;
          merged = true;
        }
        const auto rs = find(s), rt = find(t);
        if (rs != rt) parent_[rs] = rt;
      }
    }
  }
  if (merged) return Merge::merged;
  return shortest <= min2 ? Merge::failed : Merge::none;
}

void DualCellBuilder::emit_rings(std::size_t nl, CellBuffer& out) const {
  // The ring runs clockwise seen from outside the cell: emit it backwards.
  out.face_offsets.assign(roff_.begin(), roff_.end());
  out.face_vertices.resize(ring_.size());
  out.face_neighbor.resize(nl);
  for (std::uint32_t a = 0; a < nl; ++a) {
    const std::uint32_t b = roff_[a], e = roff_[a + 1];
    for (auto k = b; k < e; ++k) out.face_vertices[b + (e - 1 - k)] = ring_[k];
    out.face_neighbor[a] = static_cast<std::int32_t>(global_[a]);
  }
}

bool DualCellBuilder::emit_merged_rings(std::size_t nl, std::size_t nt, double min_edge, CellBuffer& out) {
  const double min2 = min_edge * min_edge;
  lcc_.assign(out.vertices.begin(), out.vertices.end());
  out.vertices.clear();
  out.vertices.reserve(nt);
  out.face_offsets.reserve(nl + 1);
  out.face_offsets.assign(1, 0);
  out.face_vertices.clear();
  out.face_vertices.reserve(3 * nt);
  out.face_neighbor.clear();
  out.face_neighbor.reserve(nl);
  vid_.assign(nt, kNone);
  auto vertex_of = [&](std::uint32_t root) {
    if (vid_[root] == kNone) {
      vid_[root] = static_cast<std::uint32_t>(out.vertices.size());
      out.vertices.push_back(lcc_[root]);
    }
    return vid_[root];
  };
  for (std::uint32_t a = 0; a < nl; ++a) {
    const std::uint32_t b = roff_[a], e = roff_[a + 1];
    const std::size_t start = out.face_vertices.size();
    // The ring runs clockwise seen from outside the cell: emit it backwards.
    for (auto k = e; k-- > b;) {
      const std::uint32_t r = find(ring_[k]);
      const std::uint32_t id = vertex_of(r);
      if (out.face_vertices.size() > start && out.face_vertices.back() == id) continue;
      out.face_vertices.push_back(id);
    }
    if (out.face_vertices.size() - start > 1 && out.face_vertices.back() == out.face_vertices[start])
      out.face_vertices.pop_back();
    const std::size_t m = out.face_vertices.size() - start;
    if (m == 1) {  // a Delaunay edge inside a cospherical cluster
      out.face_vertices.pop_back();
      continue;
    }
    if (m < 3) return false;
    for (std::size_t k = start; k < start + m; ++k) {
      const std::uint32_t p = out.face_vertices[k], q = out.face_vertices[k + 1 < start + m ? k + 1 : start];
      if (dist2(out.vertices[p], out.vertices[q]) <= min2) return false;
      for (std::size_t j = k + 1; j < start + m; ++j)
        if (out.face_vertices[j] == p) return false;  // a corner twice: no polygon
    }
    out.face_offsets.push_back(static_cast<std::uint32_t>(out.face_vertices.size()));
    out.face_neighbor.push_back(static_cast<std::int32_t>(global_[a]));
  }
  return true;
}

bool DualCellBuilder::closed_and_oriented(const CellBuffer& out) {
  const long f = static_cast<long>(out.face_neighbor.size());
  if (f < 4 || long(out.vertices.size()) - long(out.face_vertices.size() / 2) + f != 2) return false;
  // Every directed edge once, its reverse once.
  edges_.clear();
  for (std::size_t g = 0; g + 1 < out.face_offsets.size(); ++g) {
    const auto b = out.face_offsets[g], e = out.face_offsets[g + 1];
    for (auto k = b; k < e; ++k)
      edges_.push_back((std::uint64_t(out.face_vertices[k]) << 32) | out.face_vertices[k + 1 < e ? k + 1 : b]);
  }
  std::sort(edges_.begin(), edges_.end());
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    if (k && edges_[k] == edges_[k - 1]) return false;
    const std::uint64_t rev = (edges_[k] << 32) | (edges_[k] >> 32);
    if (!std::binary_search(edges_.begin(), edges_.end(), rev)) return false;
  }
  return true;
}

bool DualCellBuilder::build(std::uint32_t v, std::span<const std::uint32_t> star, std::span<const Tet> tets,
                            std::span<const Point3> cc, std::span<const char> bad, double band, double min_edge,
                            CellBuffer& out) {
  prefetch_ = cc.data();
  const bool ok = gather(v, star, tets, bad);
  prefetch_ = nullptr;
  if (!ok) return false;
  const std::size_t nl = global_.size(), nt = star.size();
  // Link Euler characteristic: a closed sphere has V - E + F = 2 with E = 3F/2.
  if (nt < 4 || 2 * nl != nt + 4) return false;
  if (!link_rings(nl, nt)) return false;
  // Without coincident centres the cell's vertices are the link triangles' centres,
  // one each, in link triangle order: write them straight into the output.
  out.vertices.resize(nt);
  for (std::uint32_t t = 0; t < nt; ++t) out.vertices[t] = cc[star[t]];
  switch (merge_close_centres(nl, nt, out.vertices.data(), band, min_edge)) {
    case Merge::failed: return false;
    case Merge::none: emit_rings(nl, out); return true;
    case Merge::merged: break;
  }
  return emit_merged_rings(nl, nt, min_edge, out) && closed_and_oriented(out);
}

}  // namespace dtlab::vor
