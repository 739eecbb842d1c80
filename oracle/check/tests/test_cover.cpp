// The single-cover proof (stage 6) through the whole checker: a double cover whose
// adjacency, orientation, manifoldness, edge convexity, Euler numbers and exact
// volume identity are all consistent must still be refused, at any scale; and the
// crossing count decides on rays that hit an edge or a vertex.
#include <catch2/catch.hpp>

#include <cmath>

#include "oracle/check/check.hpp"
#include "oracle/check/facet_table.hpp"
#include "oracle/check/hull_degree.hpp"
#include "oracle/check/tests/check_helpers.hpp"
#include "predicates/exact.hpp"

using namespace dtlab;
using dtlab::test::count;
using dtlab::test::orient;
using dtlab::test::summary;

namespace {

Tetrahedralization scaled(Tetrahedralization t, int e) {
  for (Point3& p : t.points) p = {std::ldexp(p.x, e), std::ldexp(p.y, e), std::ldexp(p.z, e)};
  return t;
}

// A bipyramid with apexes N, S over an equator polygon that winds twice around the
// axis: an outer triangle, then an inner one. Every turn of the equator is convex,
// so every boundary edge is convex; each vertex link is one cycle; the tets around
// the axis N-S wrap 720 degrees. Tet 0 (over the inner edge r3 r4) has all its
// vertices inside every boundary plane, so the checker reaches the degree count.
Tetrahedralization double_cover() {
  Tetrahedralization t;
  t.points = {{0, 0, 10}, {0, 0, -10}};
  const double ring[6][2] = {{20, 0}, {-10, 17}, {-10, -17}, {8, 0}, {-4, 7}, {-4, -7}};
  for (const auto& r : ring) t.points.push_back({r[0], r[1], 0});
  for (int i = 0; i < 6; ++i) {
    const int k = (i + 3) % 6;  // start with the inner edge r3 r4
    t.tets.push_back({0, 1, static_cast<std::uint32_t>(2 + k), static_cast<std::uint32_t>(2 + (k + 1) % 6)});
  }
  orient(t);
  return t;
}

}  // namespace

TEST_CASE("a consistent double cover is an overlap at scales 1, 2^-350, 2^+350", "[check][cover]") {
  for (int e : {0, -350, 350}) {
    const CheckReport r = check_tetrahedralization(scaled(double_cover(), e), {.volume_identity = true});
    INFO("scale 2^" << e << "\n" << summary(r));
    CHECK_FALSE(r.ok());
    REQUIRE(count(r, DefectKind::overlap) == 1);
    bool from_degree = false;
    for (const Defect& d : r.defects)
      if (d.kind == DefectKind::overlap && d.detail.find("crosses 2 boundary facets") != std::string::npos)
        from_degree = true;
    CHECK(from_degree);
    // Everything local is consistent: only the degree count can see it.
    for (DefectKind k : {DefectKind::broken_adjacency, DefectKind::inverted, DefectKind::flat,
                         DefectKind::hull_not_convex, DefectKind::gap, DefectKind::missing_point,
                         DefectKind::duplicate_vertex, DefectKind::euler, DefectKind::unproven})
      CHECK(count(r, k) == 0);
    CHECK(r.stats.euler == 1);
    CHECK(r.stats.boundary_euler == 2);
    CHECK(r.stats.volume_equal);  // the volume identity cannot see a double cover
    CHECK(r.stats.degree_checked);
    CHECK_FALSE(r.stats.cover_proven);
  }
}

TEST_CASE("valid meshes are proven at scales 1, 2^-350, 2^+350", "[check][cover]") {
  Tetrahedralization star;
  star.points = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}, {1, 1, 1}};
  star.tets = {{4, 1, 2, 3}, {0, 4, 2, 3}, {0, 1, 4, 3}, {0, 1, 2, 4}};
  orient(star);
  for (int e : {0, -350, 350, -1000, 1000}) {
    const CheckReport r = check_tetrahedralization(scaled(star, e));
    INFO("scale 2^" << e << "\n" << summary(r));
    CHECK(r.ok());
    CHECK(r.stats.cover_proven);
  }
}

TEST_CASE("the crossing count decides on rays through a vertex or an edge", "[check][cover]") {
  // o = centroid of the inner tet = origin; q = centroid of facet 0 of the outer tet,
  // on the ray towards -(1,1,1). A second surface has a vertex (or an edge) exactly on
  // that ray: an unperturbed count would be ambiguous there.
  std::vector<Point3> P = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};        // inner
  for (int i = 0; i < 4; ++i) P.push_back({10 * P[i].x, 10 * P[i].y, 10 * P[i].z});  // outer 4..7
  P.insert(P.end(), {{-2, -2, -2}, {6, -1, -1}, {-1, 6, -1}, {-1, -1, 6}});          // vertex on the ray: 8..11
  P.insert(P.end(), {{-3, -1, -2}, {-1, -3, -2}, {4, 4, -1}, {0, 0, 5}});            // edge across the ray: 12..15
  auto surface = [&](Tet k) {
    if (ExactPredicates{}.orient3d(P[k[0]], P[k[1]], P[k[2]], P[k[3]]) < 0) std::swap(k[0], k[1]);
    std::vector<std::array<std::uint32_t, 3>> s;
    for (int f = 0; f < 4; ++f) s.push_back(facet_vertices(k, f));
    return s;
  };
  Tet inner = {0, 1, 2, 3};
  if (ExactPredicates{}.orient3d(P[0], P[1], P[2], P[3]) < 0) std::swap(inner[0], inner[1]);
  auto outer = surface({4, 5, 6, 7});
  // Facet 0 must be the one opposite vertex 4 (centroid on the ray towards -(1,1,1)).
  for (std::size_t f = 0; f < outer.size(); ++f)
    if (std::find(outer[f].begin(), outer[f].end(), 4u) == outer[f].end()) std::swap(outer[0], outer[f]);
  for (const Tet second : {Tet{8, 9, 10, 11}, Tet{12, 13, 14, 15}}) {
    auto both = outer;
    for (const auto& f : surface(second)) both.push_back(f);
    const HullDegree d = hull_degree(P, both, inner, 0);
    INFO("second surface " << second[0]);
    REQUIRE(d.decided);
    CHECK(d.crossed.size() == 2);
    CHECK(d.crossed[0] == 0);
  }
}
