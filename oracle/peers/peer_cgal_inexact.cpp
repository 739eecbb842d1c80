// The one translation unit with CGAL's inexact kernel (CGAL compiles slowly).
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <chrono>
#include <utility>

#include "oracle/peers/peer_programs.hpp"

namespace dtlab {
namespace {

using K = CGAL::Simple_cartesian<double>;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
using Tds = CGAL::Triangulation_data_structure_3<Vb>;
using Dt = CGAL::Delaunay_triangulation_3<K, Tds>;

}  // namespace

PeerAnswer peer_cgal_inexact(const std::vector<Point3>& points) {
  std::vector<std::pair<K::Point_3, std::uint32_t>> in;
  in.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    in.emplace_back(K::Point_3(points[i].x, points[i].y, points[i].z), static_cast<std::uint32_t>(i));
  PeerAnswer a;
  const auto start = std::chrono::steady_clock::now();
  try {
    Dt dt(in.begin(), in.end());
    a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (dt.dimension() == 3)
      for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
        a.tets.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
  } catch (const CGAL::Failure_exception& e) {
    throw PeerRefusal(std::string("CGAL ") + e.what());
  }
  return a;
}

}  // namespace dtlab
