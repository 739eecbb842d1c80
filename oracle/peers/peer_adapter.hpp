#pragma once
// The adapter every peer's answer goes through before the checker sees it.
#include <span>

#include "oracle/peers/peer_exchange.hpp"
#include "oracle/peers/peers.hpp"

namespace dtlab {

// How a peer orients the tets it writes.
enum class PeerOrientation {
  dtlab,    // orient3d > 0 already (TetGen's .ele after read_ele, CGAL via cgal_delaunay, dtlab)
  swapped,  // the opposite convention, consistently (CGAL's raw cells): two vertices swapped
  by_sign,  // no orientation contract (qhull, scipy, gmsh): the exact orient3d sign decides
};

// Fills run.mesh (over the input points), run.unused, run.extra_vertices,
// run.extra_tets and run.collapsed_tets from a peer's answer:
// - an extra vertex with an input point's exact coordinates becomes that point, and
//   every copy of a duplicated input point becomes its first copy; a tet that then
//   spans two copies of one point has no volume and is left out (collapsed_tets),
//   while a tet the peer wrote with a repeated index is kept for the checker;
// - tets on any other vertex (not an input point, or an index out of range) are left
//   out and counted (extra_tets; extra_vertices: distinct such vertices);
// - orientation is made dtlab's (orient3d > 0; flat tets stay flat);
// - inputs in no tet are listed in run.unused (the checker verifies each is an exact
//   duplicate of a vertex; else it is a missing point).
void normalise_answer(std::span<const Point3> points, const PeerAnswer& answer, PeerOrientation orientation,
                      PeerRun& run);

// Runs the exact checker on run.mesh (run.unused as the producer's duplicates) and
// sets run.report and run.verdict (extra-points when extra tets were left out).
void judge_answer(PeerRun& run, unsigned threads = 1);

// The step every peer run ends with, whoever ran the peer (a helper, TetGen, a
// command, a host function): its answer adapted (normalise_answer) and, when `check`,
// judged on `threads` threads (judge_answer).
void adapt_and_judge(std::span<const Point3> points, const PeerAnswer& answer, PeerOrientation orientation, bool check,
                     unsigned threads, PeerRun& run);

}  // namespace dtlab
