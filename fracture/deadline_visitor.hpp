#pragma once
// A corefinement visitor that turns a time budget into BooleanTimeout at CGAL's
// progress callbacks: a slow boolean becomes a named failure, never a hang. Only for
// the CGAL translation units (cell_boolean.cpp, mesh_repair.cpp).
#include <chrono>

#include <CGAL/Polygon_mesh_processing/corefinement.h>

#include "fracture/cell_boolean.hpp"

namespace dtlab {

template <class Mesh>
struct DeadlineVisitor : CGAL::Polygon_mesh_processing::Corefinement::Default_visitor<Mesh> {
  std::chrono::steady_clock::time_point deadline;
  double budget = 0;  // seconds; 0: no limit

  explicit DeadlineVisitor(double seconds) : budget(seconds) {
    deadline = std::chrono::steady_clock::now() +
               std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
  }
  void check() const {
    if (budget > 0 && std::chrono::steady_clock::now() > deadline) throw BooleanTimeout(budget);
  }
  void progress_filtering_intersections(double) const { check(); }
  void triangulating_faces_step() const { check(); }
  void intersection_of_coplanar_faces_step() const { check(); }
  void edge_face_intersections_step() const { check(); }
  void start_building_output() const { check(); }
  template <class V>
  void new_vertex_added(std::size_t, V, const Mesh&) { check(); }
};

}  // namespace dtlab
