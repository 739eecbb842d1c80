#pragma once
// build_delaunay for one backend: insertion order, the starting tetrahedron, the
// boundary (infinite vertex or big enclosing tetrahedron), the insertion loop and
// the compaction of the result. Instantiated once per backend in build.cpp.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <vector>

#include "kernel/build.hpp"
#include "kernel/canonical_order.hpp"
#include "kernel/enclosing_tet.hpp"
#include "kernel/ids.hpp"
#include "kernel/inserter.hpp"
#include "kernel/insertion_log.hpp"
#include "kernel/page_release.hpp"
#include "kernel/parallel_build.hpp"
#include "kernel/parallel_for.hpp"
#include "kernel/progress.hpp"
#include "kernel/spatial_order.hpp"

namespace dtlab {

namespace detail {

template <PredicateBackend B>
bool collinear(const B& pred, const Point3& a, const Point3& b, const Point3& c) {
  // Collinear iff all three coordinate projections are (orient3d on zeroed copies).
  const auto proj = [&](auto get) { return pred.orient3d(get(a), get(b), get(c), Point3{0, 0, 1}); };
  return proj([](const Point3& p) {
           return Point3{p.x, p.y, 0};
         }) == 0 &&
         proj([](const Point3& p) {
           return Point3{p.y, p.z, 0};
         }) == 0 &&
         proj([](const Point3& p) {
           return Point3{p.z, p.x, 0};
         }) == 0;
}

// The finite live tets, vertex ids translated back to input indices (vertex v is
// input point order[v]), and with `adjacency` non-null each facet's mirror among them
// (Tetrahedralization::adjacency). The records' pages are handed back as they are read
// (the caller frees the buffer): the mesh cannot be used afterwards.
inline void compact(TetRecord* records, std::size_t size, std::uint32_t n, const std::vector<std::uint32_t>& order,
                    std::vector<Tet>& out, std::vector<std::uint32_t>* adjacency = nullptr) {
  const auto finite = [n](const TetRecord& r) {
    return r.v[0] < n && r.v[1] < n && r.v[2] < n && r.v[3] < n;  // dead tets have v[0] == kNone
  };
  // With adjacency: each record's index among the finite tets (kNone for the others).
  std::vector<std::uint32_t> index(adjacency ? size : 0, kNone);
  std::size_t count = 0;
  for (std::size_t t = 0; t < size; ++t)
    if (finite(records[t])) {
      if (adjacency) index[t] = static_cast<std::uint32_t>(count);
      ++count;
    }
  out.clear();
  out.reserve(count);
  if (adjacency) adjacency->clear(), adjacency->reserve(4 * count);
  constexpr std::size_t kChunk = 1 << 15;  // records between two releases (1 MiB)
  const char* unreleased = reinterpret_cast<const char*>(records);
  for (std::size_t start = 0; start < size; start += kChunk) {
    const std::size_t stop = std::min(size, start + kChunk);
    for (std::size_t t = start; t < stop; ++t) {
      const TetRecord& r = records[t];
      if (!finite(r)) continue;
      out.push_back({order[r.v[0]], order[r.v[1]], order[r.v[2]], order[r.v[3]]});
      if (adjacency)
        for (const Facet m : r.adj) {
          const std::uint32_t u = m.none() ? kNone : index[m.tet()];
          adjacency->push_back(u == kNone ? kNone : 4 * u + static_cast<std::uint32_t>(m.face()));
        }
    }
    unreleased = release_pages(unreleased, reinterpret_cast<const char*>(records + stop));
  }
}

// Moves points[k] to position order[k] for every k, in place, by following the cycles of
// the permutation (order is consumed: it ends as the identity). No second copy of the
// points, but a miss on nearly every step.
inline void follow_cycles(std::vector<Point3>& points, std::vector<std::uint32_t>& order) {
  for (std::size_t s = 0; s < order.size(); ++s)
    while (order[s] != s) {
      const std::uint32_t j = order[s];
      std::swap(points[s], points[j]);
      std::swap(order[s], order[j]);
    }
}

// Through a second copy of the points on `threads` threads: a gather (restore false:
// copy[k] = points[order[k]]) or a scatter (restore true: copy[order[k]] = points[k]),
// then swapped in. The copy is transient, taken before the tet records exist or after
// they are gone, so it stays below the build's peak memory.
inline void permute_through_copy(std::vector<Point3>& points, const std::vector<std::uint32_t>& order, bool restore,
                                 unsigned threads) {
  const std::size_t n = order.size();
  std::vector<Point3> copy;
  copy.reserve(points.capacity());
  copy.resize(n);
  parallel_for(n, threads, std::size_t(1) << 15, [&](std::size_t k, unsigned) {
    if (restore)
      copy[order[k]] = points[k];
    else
      copy[k] = points[order[k]];
  });
  points.swap(copy);
}

// The renumbering into insertion order: afterwards points[k] is the input's
// points[order[k]]. One thread: in place (no copy); more: the parallel gather.
inline void to_insertion_order(std::vector<Point3>& points, const std::vector<std::uint32_t>& order, unsigned threads) {
  if (threads > 1) return permute_through_copy(points, order, false, threads);
  std::vector<std::uint32_t> rank(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) rank[order[k]] = static_cast<std::uint32_t>(k);
  follow_cycles(points, rank);
}

// Its inverse: points[k] goes back to position order[k]. `order` is consumed (its
// contents afterwards are unspecified). One thread: in place; more: the parallel scatter.
inline void to_input_order(std::vector<Point3>& points, std::vector<std::uint32_t>& order, unsigned threads) {
  if (threads > 1) return permute_through_copy(points, order, true, threads);
  follow_cycles(points, order);
}

}  // namespace detail

// The insertion loop's report in input indices. A duplicate's vertex stands for the first
// occurrence in input order (the smallest input index of its copies): each pair swaps the
// two indices when the point not inserted came first, in any order of the pairs.
inline void resolve_log(BuildResult& res, const InsertionLog& log, std::vector<std::uint32_t>& order) {
  for (const auto& [k, v] : log.duplicates) {
    if (order[k] < order[v]) std::swap(order[k], order[v]);
    res.duplicates.push_back(order[k]);
  }
  std::sort(res.duplicates.begin(), res.duplicates.end());
  if (log.failure) res.failure = BuildFailure{log.failure->kind, order[log.failure->rank], log.failure->detail};
  for (const std::uint32_t k : log.skipped) res.skipped.push_back(order[k]);
  std::sort(res.skipped.begin(), res.skipped.end());
}

// What the insertion stages share: the renumbered points, the first tet, the log of
// duplicates and failures, the result they fill (stats, tets) and the progress hook.
template <PredicateBackend B>
struct InsertionJob {
  std::vector<Point3>& pts;
  const B& pred;
  const BuildOptions& opt;
  std::vector<std::uint32_t>& order;
  BuildResult& res;
  std::uint32_t n, inf;
  std::uint32_t first[4];
  bool infinite;
  unsigned threads;
  Progress* progress;
  std::chrono::steady_clock::time_point t0;
  InsertionLog log;
  // With the infinite vertex, the first tet's vertices are input points inserted first.
  bool is_first(std::uint32_t k) const {
    return infinite && (k == first[0] || k == first[1] || k == first[2] || k == first[3]);
  }
};

// The serial build: one inserter, the points in BRIO order; fills j.res.
template <PredicateBackend B>
void insert_serially(InsertionJob<B>& j) {
  Inserter<B> ins(j.pts.data(), j.pred, j.inf, j.opt.seed);
  ins.reserve(j.n);
  ins.check_combinatorics(j.opt.check_combinatorics, j.pts.size());
  ins.start(j.first[0], j.first[1], j.first[2], j.first[3]);
  if (j.infinite) ins.stats().inserted = 4;
  for (std::uint32_t k = 0; k < j.n; ++k) {
    progress_advance(j.progress, k);
    if (j.is_first(k)) continue;
    const auto outcome = ins.insert(k);
    if (outcome == Inserter<B>::Outcome::duplicate) {
      j.log.duplicates.push_back({k, ins.found()});
    } else if (outcome == Inserter<B>::Outcome::failed) {
      j.log.failure = InsertionLog::Failure{k, ins.failure(), ins.failure_detail()};
      for (std::uint32_t q = k; q < j.n; ++q)
        if (!j.is_first(q)) j.log.skipped.push_back(q);
      break;
    }
  }
  j.res.stats = ins.stats();
  j.res.stats.orient3d_calls = ins.geometry().orient_calls;
  j.res.stats.insphere_calls = ins.geometry().insphere_calls;
  j.res.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - j.t0).count();
  j.res.peak_tets = ins.mesh().size();
  resolve_log(j.res, j.log, j.order);
  std::vector<TetRecord>& records = ins.mesh().records();
  detail::compact(records.data(), records.size(), j.n, j.order, j.res.mesh.tets,
                  j.opt.keep_adjacency ? &j.res.mesh.adjacency : nullptr);
  std::vector<TetRecord>().swap(records);
}

// The end of the threaded build: statistics, the log in input indices, the tets compacted.
template <PredicateBackend B>
void finish_threaded(InsertionJob<B>& j, ParallelInsertion<B>& par) {
  j.res.stats = par.finish();
  if (j.infinite) j.res.stats.inserted += 4;
  j.res.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - j.t0).count();
  j.res.peak_tets = par.store().size();
  resolve_log(j.res, j.log, j.order);
  // With keep_adjacency: a copy of the records, read again once the tets are in place.
  std::vector<TetRecord> copy;
  if (j.opt.keep_adjacency) copy.assign(par.store().records(), par.store().records() + par.store().size());
  compact_canonical(par.store().records(), par.store().size(), j.n, j.order, j.res.mesh.tets, j.threads);
  std::free(par.store().release_records());
  if (j.opt.keep_adjacency)
    j.res.mesh.adjacency = canonical_adjacency(copy.data(), copy.size(), j.n, j.order, j.res.mesh.tets, j.threads);
}

// The threaded build (kernel/parallel_build.hpp); fills j.res.
template <PredicateBackend B>
void insert_threaded(InsertionJob<B>& j) {
  ParallelInsertion<B> par(j.pts.data(), j.n, j.inf, j.pred, j.opt, j.threads);
  par.start(j.first, 4);
  // BRIO rounds one after the other (the input order is one round).
  const std::vector<std::size_t> rounds =
      j.opt.order == InsertionOrder::brio ? brio_rounds(j.n) : std::vector<std::size_t>{0, j.n};
  // A round is inserted in slices of at most kProgressSlice points so that the progress
  // hook (which may cancel the build: Ctrl-C in Python) runs every few tenths of a second,
  // not once per round (the last BRIO round holds 7/8 of the points).
  constexpr std::size_t kProgressSlice = std::size_t(1) << 17;
  for (std::size_t r = 0; r + 1 < rounds.size(); ++r) {
    for (std::size_t s = rounds[r]; s < rounds[r + 1]; s += kProgressSlice) {
      const std::size_t e = std::min(rounds[r + 1], s + kProgressSlice);
      progress_advance(j.progress, s);  // on the calling thread, between passes
      std::vector<std::uint32_t> list;
      list.reserve(e - s);
      for (std::size_t k = s; k < e; ++k)
        if (!j.is_first(static_cast<std::uint32_t>(k))) list.push_back(static_cast<std::uint32_t>(k));
      if (!par.insert(std::move(list), j.log)) {
        for (std::size_t k = e; k < j.n; ++k)
          if (!j.is_first(static_cast<std::uint32_t>(k))) j.log.skipped.push_back(static_cast<std::uint32_t>(k));
        return finish_threaded(j, par);
      }
    }
  }
  finish_threaded(j, par);
}

// The first four affinely independent points in insertion order, as positions in `pts`
// (either boundary: a lower-dimensional input has no Delaunay tetrahedralization).
// Returns why there are none, or nullptr.
template <PredicateBackend B>
const char* first_simplex(const std::vector<Point3>& pts, std::uint32_t n, const B& pred, std::uint32_t (&first)[4]) {
  if (n < 4) return "fewer than 4 points";
  std::uint32_t k = 1;
  const auto next = [&](auto accept) {
    for (; k < n; ++k)
      if (accept(pts[k])) return true;
    return false;
  };
  first[0] = 0;
  const Point3 a = pts[0];
  if (!next([&](const Point3& q) { return !(q == a); })) return "all points coincide";
  first[1] = k++;
  const Point3 b = pts[first[1]];
  if (!next([&](const Point3& q) { return !detail::collinear(pred, a, b, q); })) return "all points are collinear";
  first[2] = k++;
  const Point3 c = pts[first[2]];
  if (!next([&](const Point3& q) { return pred.orient3d(a, b, c, q) != 0; })) return "all points are coplanar";
  first[3] = k;
  return nullptr;
}

// `pts` holds the input points in input order; the build owns it, permutes it in place
// and hands it back in input order as the result's points (no second copy).
template <PredicateBackend B>
BuildResult build_with(std::vector<Point3> pts, const B& pred, const BuildOptions& opt) {
  BuildResult res;
  const auto n = static_cast<std::uint32_t>(pts.size());
  // Vertex ids are insertion ranks: vertex k is input point order[k], stored at
  // pts[k], so consecutive insertions read neighbouring coordinates. The output is
  // translated back to input indices.
  const unsigned threads = std::min(thread_count(opt.threads), kMaxBuildThreads);
  std::vector<std::uint32_t> order;
  if (opt.order == InsertionOrder::brio) {
    order = brio_order(pts, opt.seed, threads);
  } else {
    order.resize(n);
    std::iota(order.begin(), order.end(), 0u);
  }
  // The bigtet is computed from the input before the renumbering (it reads every point).
  std::optional<EnclosingTet> big;
  if (opt.boundary == Boundary::bigtet && n >= 4) big = enclosing_tet(pts, opt.bigtet_factor);
  pts.reserve(std::size_t(n) + 4);  // room for the infinite vertex or the bigtet corners
  detail::to_insertion_order(pts, order, threads);

  // The points go back to input order (a copy of `order`: restoring consumes it).
  const auto give_back_points = [&] {
    pts.resize(n);
    std::vector<std::uint32_t> o = order;
    detail::to_input_order(pts, o, threads);
    res.mesh.points = std::move(pts);
  };
  auto lower_dimensional = [&](const char* why) {
    res.failure = BuildFailure{FailureKind::lower_dimensional, -1, why};
    res.skipped.resize(n);
    std::iota(res.skipped.begin(), res.skipped.end(), 0u);
    give_back_points();
    return res;
  };

  std::uint32_t inf = kNone;
  std::uint32_t first[4];
  if (const char* why = first_simplex(pts, n, pred, first)) return lower_dimensional(why);
  const Point3 a = pts[first[0]], b = pts[first[1]], c = pts[first[2]];
  if (opt.boundary == Boundary::infinite) {
    if (pred.orient3d(a, b, c, pts[first[3]]) < 0) std::swap(first[0], first[1]);
    pts.push_back(a);  // the infinite vertex's slot: its coordinates are never read
    inf = n;
  } else {
    // The thesis's big enclosing tetrahedron, proven to hold every point (exactly).
    if (!big->valid()) {
      res.failure = BuildFailure{FailureKind::outside_boundary, -1, big->defect};
      res.skipped = order;
      std::sort(res.skipped.begin(), res.skipped.end());
      give_back_points();
      return res;
    }
    for (const Point3& q : big->corners) pts.push_back(q);
    first[0] = n, first[1] = n + 1, first[2] = n + 2, first[3] = n + 3;
    if (pred.orient3d(pts[n], pts[n + 1], pts[n + 2], pts[n + 3]) < 0) std::swap(first[0], first[1]);
  }

  InsertionJob<B> job{pts,
                      pred,
                      opt,
                      order,
                      res,
                      n,
                      inf,
                      {first[0], first[1], first[2], first[3]},
                      opt.boundary == Boundary::infinite,
                      threads,
                      thread_progress(),
                      {},
                      {}};
  progress_begin(job.progress, "insert", n);  // stage "insert": points of the order done
  job.t0 = std::chrono::steady_clock::now();
  if (job.threads <= 1 && !opt.canonical_order)
    insert_serially(job);
  else
    insert_threaded(job);
  if (!res.failure) progress_advance(job.progress, n);
  pts.resize(n);
  detail::to_input_order(pts, order, threads);
  res.mesh.points = std::move(pts);
  return res;
}

}  // namespace dtlab
