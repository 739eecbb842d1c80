// CGAL's parallel Delaunay_triangulation_3 (Parallel_tag, oneTBB, a lock grid of 50^3
// cells over the bounding box, as in CGAL's own parallel example), on `threads`
// threads. Its own translation unit: only it needs TBB.
#include <chrono>
#include <utility>

#include "oracle/peers/peer_programs.hpp"

#if DTLAB_HAVE_TBB
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <tbb/global_control.h>
#endif

namespace dtlab {

#if DTLAB_HAVE_TBB

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
using Cb = CGAL::Delaunay_triangulation_cell_base_3<K>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb, CGAL::Parallel_tag>;
using Dt = CGAL::Delaunay_triangulation_3<K, Tds>;

CGAL::Bbox_3 bounding_box(const std::vector<Point3>& points) {
  CGAL::Bbox_3 box;
  for (const Point3& p : points) box += CGAL::Bbox_3(p.x, p.y, p.z, p.x, p.y, p.z);
  return box;
}
}  // namespace

PeerAnswer peer_cgal_parallel(const std::vector<Point3>& points, unsigned threads) {
  if (threads == 0) throw std::invalid_argument("cgal-parallel: thread count 0");
  std::vector<std::pair<K::Point_3, std::uint32_t>> in;
  in.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    in.emplace_back(K::Point_3(points[i].x, points[i].y, points[i].z), static_cast<std::uint32_t>(i));
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  PeerAnswer a;
  const auto start = std::chrono::steady_clock::now();
  try {
    Dt::Lock_data_structure locks(bounding_box(points), 50);
    Dt dt(in.begin(), in.end(), &locks);
    a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (dt.dimension() == 3) {
      a.tets.reserve(dt.number_of_finite_cells());
      for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
        a.tets.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
    }
  } catch (const CGAL::Failure_exception& e) {
    throw PeerRefusal(std::string("CGAL ") + e.what());
  }
  return a;
}

#else

PeerAnswer peer_cgal_parallel(const std::vector<Point3>&, unsigned) {
  throw PeerNotInstalled("built without oneTBB (Debian libtbb-dev)");
}

#endif

}  // namespace dtlab
