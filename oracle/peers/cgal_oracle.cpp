#include "oracle/peers/cgal_oracle.hpp"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/spatial_sort.h>

#include <chrono>
#include <utility>
#include <vector>

namespace dtlab {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
using Tds = CGAL::Triangulation_data_structure_3<Vb>;
using Dt = CGAL::Delaunay_triangulation_3<K, Tds>;

}  // namespace

OracleRun cgal_delaunay(std::span<const Point3> points) {
  OracleRun run;
  run.name = "cgal";
  std::vector<std::pair<K::Point_3, std::uint32_t>> in;
  in.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    in.emplace_back(K::Point_3(points[i].x, points[i].y, points[i].z), static_cast<std::uint32_t>(i));
  const auto start = std::chrono::steady_clock::now();
  Dt dt(in.begin(), in.end());
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  Tetrahedralization t;
  t.points.assign(points.begin(), points.end());
  std::vector<char> is_vertex(points.size(), 0);
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) is_vertex[v->info()] = 1;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!is_vertex[i]) run.duplicates.push_back(static_cast<std::uint32_t>(i));
  if (dt.dimension() == 3) {
    t.tets.reserve(dt.number_of_finite_cells());
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
      t.tets.push_back({c->vertex(1)->info(), c->vertex(0)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
  } else {
    run.note = "input spans dimension " + std::to_string(dt.dimension()) + ": no tets";
  }
  run.mesh = std::move(t);
  return run;
}

std::vector<std::uint32_t> cgal_spatial_sort_order(std::span<const Point3> points) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Point_3> pts;
  pts.reserve(points.size());
  for (const Point3& p : points) pts.emplace_back(p.x, p.y, p.z);
  std::vector<std::size_t> index(points.size());  // the property map's key type
  for (std::size_t i = 0; i < index.size(); ++i) index[i] = i;
  using Map = CGAL::Pointer_property_map<K::Point_3>::type;
  CGAL::Spatial_sort_traits_adapter_3<K, Map> traits(CGAL::make_property_map(pts));
  CGAL::spatial_sort(index.begin(), index.end(), traits);
  std::vector<std::uint32_t> order(index.begin(), index.end());
  return order;
}

}  // namespace dtlab
