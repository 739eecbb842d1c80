// The checker on small hand-built meshes: valid ones pass, each broken one is
// reported under the right defect name.
#include <catch2/catch.hpp>

#include "oracle/check/check.hpp"
#include "oracle/check/facet_table.hpp"
#include "oracle/check/hull_degree.hpp"
#include "oracle/check/report_json.hpp"
#include "oracle/check/tests/check_helpers.hpp"
#include "predicates/exact.hpp"

using namespace dtlab;
using dtlab::test::count;
using dtlab::test::orient;
using dtlab::test::summary;

namespace {

// A tet split 1-4 around an interior point: the only triangulation of its 5 points.
Tetrahedralization star() {
  Tetrahedralization t;
  t.points = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}, {1, 1, 1}};
  t.tets = {{4, 1, 2, 3}, {0, 4, 2, 3}, {0, 1, 4, 3}, {0, 1, 2, 4}};
  orient(t);
  return t;
}

// Two tets glued along triangle 012, apexes 3 and 4 on either side.
Tetrahedralization bipyramid(Point3 top, Point3 bottom) {
  Tetrahedralization t;
  t.points = {{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, top, bottom};
  t.tets = {{0, 1, 2, 3}, {0, 1, 2, 4}};
  orient(t);
  return t;
}

}  // namespace

TEST_CASE("valid small meshes pass", "[check]") {
  Tetrahedralization one;
  one.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  one.tets = {{1, 0, 2, 3}};
  for (const auto& t : {one, star(), bipyramid({1, 1, 5}, {1, 1, -5})}) {
    const CheckReport r = check_tetrahedralization(t, {.volume_identity = true});
    INFO(summary(r));
    CHECK(r.ok());
    CHECK(r.stats.cover_proven);
    CHECK(r.stats.euler == 1);
    CHECK(r.stats.boundary_euler == 2);
    CHECK(r.stats.degree_checked);
    CHECK(r.stats.volume_equal);
  }
  CHECK(check_tetrahedralization(star()).stats.volume_hull == Approx(32.0 / 3.0));
  CHECK(check_tetrahedralization(star(), {.volume_identity = true}).stats.volume_tets == Approx(32.0 / 3.0));
}

TEST_CASE("inverted and flat tets", "[check]") {
  Tetrahedralization t = star();
  std::swap(t.tets[0][0], t.tets[0][1]);
  CHECK(count(check_tetrahedralization(t), DefectKind::inverted) == 1);

  Tetrahedralization f = star();
  f.points.push_back({2, 2, 0});  // on the facet 0,1,2... plane z = 0
  f.tets.push_back({0, 1, 2, 5});
  const CheckReport r = check_tetrahedralization(f);
  CHECK(count(r, DefectKind::flat) == 1);
  CHECK_FALSE(r.ok());
}

TEST_CASE("broken adjacency: repeated vertex, facet in three tets", "[check]") {
  Tetrahedralization t = star();
  t.tets[1] = {0, 0, 2, 3};
  CHECK(count(check_tetrahedralization(t), DefectKind::broken_adjacency) >= 1);

  Tetrahedralization b = bipyramid({1, 1, 5}, {1, 1, -5});
  b.points.push_back({1, 1, 6});
  b.tets.push_back({0, 1, 2, 5});
  orient(b);
  const CheckReport r = check_tetrahedralization(b);
  INFO(summary(r));
  CHECK(count(r, DefectKind::broken_adjacency) >= 1);
}

TEST_CASE("overlap: two tets on the same side of their shared facet", "[check]") {
  Tetrahedralization b = bipyramid({1, 1, 5}, {1, 1, -5});
  b.points.push_back({1, 1, 6});
  b.tets[1] = {0, 1, 2, 5};
  orient(b);
  const CheckReport r = check_tetrahedralization(b);
  INFO(summary(r));
  CHECK(count(r, DefectKind::overlap) >= 1);
  CHECK(count(r, DefectKind::missing_point) == 1);  // point 4 is unused
}

TEST_CASE("non-delaunay: a thin bipyramid needs the 2-3 flip", "[check]") {
  const CheckReport r = check_tetrahedralization(bipyramid({1, 1, 0.25}, {1, 1, -0.25}));
  INFO(summary(r));
  REQUIRE(count(r, DefectKind::non_delaunay) == 1);
  const Defect& d = r.defects[0];
  CHECK(d.kind == DefectKind::non_delaunay);
  CHECK(d.sign > 0);
  CHECK(d.tets.size() == 2);
  CHECK(d.vertices.size() == 5);
}

TEST_CASE("hull-not-convex: a reflex boundary edge", "[check]") {
  // The segment from apex to apex misses the shared triangle: the union is not convex.
  const CheckReport r = check_tetrahedralization(bipyramid({0.5, 0.5, 2}, {4, 4, -0.5}));
  INFO(summary(r));
  CHECK(count(r, DefectKind::hull_not_convex) >= 1);
  CHECK(count(r, DefectKind::non_delaunay) == 0);
}

TEST_CASE("hull-not-convex: a tet missing at the boundary", "[check]") {
  Tetrahedralization t = star();
  t.tets.pop_back();
  const CheckReport r = check_tetrahedralization(t);
  INFO(summary(r));
  CHECK(count(r, DefectKind::hull_not_convex) >= 1);
}

TEST_CASE("gap: separate pieces, and no tets for a 3D input", "[check]") {
  Tetrahedralization t;
  t.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, 0, 1}};
  t.tets = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  orient(t);
  const CheckReport r = check_tetrahedralization(t);
  INFO(summary(r));
  CHECK(count(r, DefectKind::gap) >= 1);

  Tetrahedralization empty = star();
  empty.tets.clear();
  CHECK(count(check_tetrahedralization(empty), DefectKind::gap) == 1);

  Tetrahedralization flat;
  flat.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.5, 0}};
  CHECK(check_tetrahedralization(flat).ok());
}

TEST_CASE("no tets: valid exactly when the input spans less than a volume", "[check]") {
  struct Case {
    std::vector<Point3> points;
    AffineSpan span;
    const char* words;
  };
  const double tiny = 0x1p-1074;  // the smallest subnormal: off the plane z = 0
  const std::vector<Case> cases = {
      {{}, AffineSpan::no_points, "there are no points"},
      {{{1, 2, 3}, {1, 2, 3}}, AffineSpan::point, "the points coincide"},
      {{{0, 0, 0}, {1, 1, 1}, {0, 0, 0}, {3, 3, 3}}, AffineSpan::line, "the points are collinear"},
      {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, AffineSpan::plane, "the points are coplanar"},
      {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.25, 0}}, AffineSpan::plane, "the points are coplanar"},
      {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 3, tiny}}, AffineSpan::volume, nullptr},
      // Collinear in doubles' rounding, not exactly: 0.1 * 3 != 0.3.
      {{{0, 0, 0}, {0.1, 0.1, 0.1}, {0.3, 0.3, 0.30000000000000004}}, AffineSpan::plane, "the points are coplanar"},
  };
  for (const Case& c : cases) {
    Tetrahedralization t;
    t.points = c.points;
    const CheckReport r = check_tetrahedralization(t);
    INFO(summary(r) << " / " << format_stats(r.stats));
    CHECK(r.stats.input_span == c.span);
    CHECK_FALSE(r.stats.cover_proven);  // no cover to prove: the headline says why it is right
    if (c.words) {
      CHECK(r.ok());
      CHECK(check_headline(r) == std::string("valid: no tetrahedra; ") + c.words +
                                     " (decided exactly), so the empty mesh is the Delaunay tetrahedralization");
      CHECK(to_json(r)["volume"] == 0.0);
    } else {
      CHECK(count(r, DefectKind::gap) == 1);
      CHECK(check_headline(r) == "DEFECTS FOUND");
      CHECK(format_stats(r.stats).find("cover not proven") != std::string::npos);
      CHECK(to_json(r)["volume"].is_null());
    }
  }
  // With tets the span is not decided, and "valid" keeps its usual words.
  const CheckReport star_report = check_tetrahedralization(star());
  CHECK(star_report.stats.input_span == AffineSpan::not_decided);
  CHECK(check_headline(star_report) == "valid Delaunay tetrahedralization");
}

TEST_CASE("missing points and duplicates", "[check]") {
  Tetrahedralization t = star();
  t.points.push_back({0.5, 0.5, 0.5});  // inside, not a vertex
  const CheckReport r = check_tetrahedralization(t);
  REQUIRE(count(r, DefectKind::missing_point) == 1);
  CHECK(r.defects[0].vertices == std::vector<std::uint32_t>{5});

  Tetrahedralization d = star();
  d.points.push_back({1, 1, 1});  // exact duplicate of vertex 4: fine, reported or not
  const std::vector<std::uint32_t> dup{5};
  CHECK(check_tetrahedralization(d).ok());
  CHECK(check_tetrahedralization(d, {.duplicates = dup}).ok());
  CHECK(check_tetrahedralization(d).stats.duplicates == 1);

  Tetrahedralization wrong = star();
  wrong.points.push_back({1, 1, 1 + 0x1p-52});  // reported as a duplicate but is not
  const CheckReport w = check_tetrahedralization(wrong, {.duplicates = dup});
  REQUIRE(count(w, DefectKind::missing_point) == 1);
  CHECK(w.defects[0].detail.find("reported as a duplicate") != std::string::npos);
}

TEST_CASE("the renumbering check reports in the caller's numbering", "[check]") {
  // The star with its points reversed: first appearance in the tets is not id order.
  Tetrahedralization t = star();
  const std::uint32_t n = static_cast<std::uint32_t>(t.points.size());
  std::reverse(t.points.begin(), t.points.end());
  for (Tet& k : t.tets)
    for (auto& v : k) v = n - 1 - v;
  t.points.insert(t.points.begin(), {1, 1, 1});  // id 0: a duplicate of (1,1,1), now vertex 1
  for (Tet& k : t.tets)
    for (auto& v : k) ++v;
  const std::vector<std::uint32_t> dup{0};
  CHECK(test::check_both_ways(t, {.duplicates = dup}).ok());
  // Moving one vertex makes the reported duplicate a missing point, by its own id.
  Tetrahedralization moved = t;
  moved.points[0].z += 0x1p-40;
  const CheckReport r = test::check_both_ways(moved, {.duplicates = dup});
  REQUIRE(count(r, DefectKind::missing_point) == 1);
  const CheckReport owned = check_tetrahedralization(std::move(moved), {.duplicates = dup});
  REQUIRE(owned.defects.size() == 1);
  CHECK(owned.defects[0].vertices == std::vector<std::uint32_t>{0});
  // An out-of-range id is reported before any renumbering, also by the owning overload.
  Tetrahedralization bad = t;
  bad.tets[0][2] = 99;
  const CheckReport bad_report = check_tetrahedralization(std::move(bad));
  CHECK(count(bad_report, DefectKind::broken_adjacency) == 1);
}

TEST_CASE("duplicate vertices", "[check]") {
  Tetrahedralization t;
  t.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  t.tets = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  orient(t);
  CHECK(count(check_tetrahedralization(t), DefectKind::duplicate_vertex) == 1);
}

TEST_CASE("hull_degree counts how often the boundary wraps around", "[check]") {
  const Tetrahedralization s = star();
  std::vector<std::array<std::uint32_t, 3>> once, twice;
  // The boundary of the star is the boundary of its outer tet 0,1,2,3.
  Tet outer = {0, 1, 2, 3};
  if (ExactPredicates{}.orient3d(s.points[0], s.points[1], s.points[2], s.points[3]) < 0) std::swap(outer[0], outer[1]);
  for (int f = 0; f < 4; ++f) once.push_back(facet_vertices(outer, f));
  twice = once;
  twice.insert(twice.end(), once.begin(), once.end());
  const HullDegree d1 = hull_degree(s.points, once, s.tets[0], 0);
  REQUIRE(d1.decided);
  CHECK(d1.crossed == std::vector<std::uint32_t>{0});
  const HullDegree d2 = hull_degree(s.points, twice, s.tets[0], 0);
  REQUIRE(d2.decided);
  CHECK(d2.crossed == std::vector<std::uint32_t>{0, 4});
}
