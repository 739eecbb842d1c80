#include <algorithm>
#include <catch2/catch.hpp>

#include "fuzz/case_seed.hpp"
#include "fuzz/families.hpp"
#include "fuzz/shrink.hpp"

using namespace dtlab;
using namespace dtlab::fuzz;

namespace {
bool contains(const std::vector<Point3>& v, const Point3& p) {
  return std::find(v.begin(), v.end(), p) != v.end();
}
}  // namespace

TEST_CASE("shrinking keeps exactly the points a failure needs", "[fuzz][shrink]") {
  const auto pts = find_family("uniform")->generate(200, 4);
  const Point3 a = pts[17], b = pts[150], c = pts[151];
  const auto fails = [&](const std::vector<Point3>& v) {
    return contains(v, a) && contains(v, b) && contains(v, c);
  };
  const ShrinkResult r = shrink_points(pts, fails);
  CHECK(r.minimal);
  REQUIRE(r.points.size() == 3);
  CHECK(fails(r.points));
  CHECK(r.tests < 200);
}

TEST_CASE("shrinking handles a size threshold and keeps input order", "[fuzz][shrink]") {
  const auto pts = find_family("uniform")->generate(100, 5);
  const auto fails = [](const std::vector<Point3>& v) { return v.size() >= 7; };
  const ShrinkResult r = shrink_points(pts, fails);
  CHECK(r.minimal);
  CHECK(r.points.size() == 7);
  // The survivors are a subsequence of the input.
  std::size_t j = 0;
  for (const auto& p : pts)
    if (j < r.points.size() && p == r.points[j]) ++j;
  CHECK(j == r.points.size());
}

TEST_CASE("shrinking stops at its budget with a still-failing input", "[fuzz][shrink]") {
  const auto pts = find_family("uniform")->generate(500, 6);
  const auto fails = [&](const std::vector<Point3>& v) { return contains(v, pts[3]) && v.size() % 2 == 0; };
  const ShrinkResult r = shrink_points(pts, fails, 10);
  CHECK(r.tests <= 10);
  CHECK_FALSE(r.minimal);
  CHECK(fails(r.points));
}

TEST_CASE("a stopped shrink resumes where it stopped and ends as one whole shrink", "[fuzz][shrink]") {
  const auto pts = find_family("uniform")->generate(200, 4);
  const Point3 a = pts[17], b = pts[150], c = pts[151];
  const auto fails = [&](const std::vector<Point3>& v) {
    return contains(v, a) && contains(v, b) && contains(v, c);
  };
  const ShrinkResult whole = shrink_points(pts, fails);
  std::size_t calls = 0;
  const auto counted = [&](const std::vector<Point3>& v) {
    ++calls;
    return fails(v);
  };
  const ShrinkResult first = shrink_points(pts, counted, 1000, {}, [&] { return calls >= 12; });
  CHECK_FALSE(first.minimal);
  CHECK(first.tests == 12);
  CHECK(fails(first.points));
  const ShrinkResult rest = shrink_points(first.points, fails, 1000, first.position);
  CHECK(rest.minimal);
  CHECK(rest.points == whole.points);
  CHECK(first.tests + rest.tests <= whole.tests + 1);  // at most the try before the stop again

  // Resumed in steps of 3 tries (fewer than one granularity's chunks), it still gets there.
  ShrinkResult step;
  step.points = pts;
  std::size_t steps = 0;
  do {
    step = shrink_points(step.points, fails, 3, step.position);
    ++steps;
  } while (!step.minimal && steps < 1000);
  CHECK(step.minimal);
  CHECK(step.points == whole.points);
}

TEST_CASE("case seeds depend on seed, family and index only", "[fuzz][shrink]") {
  CHECK(case_seed(1, "uniform", 0) == case_seed(1, "uniform", 0));
  CHECK(case_seed(1, "uniform", 0) != case_seed(2, "uniform", 0));
  CHECK(case_seed(1, "uniform", 0) != case_seed(1, "lattice", 0));
  CHECK(case_seed(1, "uniform", 0) != case_seed(1, "uniform", 1));
  static_assert(case_seed(7, "x", 3) == case_seed(7, "x", 3));
}
