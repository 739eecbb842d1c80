#include <catch2/catch.hpp>

#include <string>

#include "families.hpp"
#include "predicates/backend_choice.hpp"
#include "predicates/counting.hpp"

using namespace dtlab;
using namespace dtlab::test;

TEST_CASE("counting counts calls, zeros and adaptive stages", "[counting]") {
  Counting<AdaptivePredicates> c;
  const Point3 a{0, 0, 0}, b{1, 0, 0}, p{0, 1, 0}, d{0, 0, -1};
  CHECK(c.orient3d(a, b, p, d) == 1);
  CHECK(c.orient3d(a, b, p, Point3{0.5, 0.25, 0}) == 0);
  CHECK(c.insphere(a, b, p, d, Point3{1, 1, 0}) == 0);
  CHECK(c.counts.orient3d_calls == 2);
  CHECK(c.counts.orient3d_zero == 1);
  CHECK(c.counts.insphere_calls == 1);
  CHECK(c.counts.insphere_zero == 1);
  std::uint64_t o = 0, i = 0;
  for (auto v : c.stages.orient3d) o += v;
  for (auto v : c.stages.insphere) i += v;
  CHECK(o == 2);
  CHECK(i == 1);
  // A copy counts into its own stages.
  Counting<AdaptivePredicates> copy = c;
  copy.orient3d(a, b, p, d);
  CHECK(copy.counts.orient3d_calls == 3);
  CHECK(c.counts.orient3d_calls == 2);
  std::uint64_t oc = 0;
  for (auto v : copy.stages.orient3d) oc += v;
  CHECK(oc == 3);
  Counting<Perturbed<AdaptivePredicates>> pc;
  CHECK(pc.insphere(a, b, p, d, Point3{1, 1, 0}) != 0);  // tie broken by orient3d calls
  std::uint64_t po = 0, pi = 0;
  for (auto v : pc.stages.orient3d) po += v;
  for (auto v : pc.stages.insphere) pi += v;
  CHECK(pi == 1);
  CHECK(po >= 1);
  CHECK(pc.counts.insphere_zero == 0);
  Counting<NaivePredicates> n;
  n.insphere(a, b, p, d, Point3{2, 2, 2});
  CHECK(n.counts.insphere_calls == 1);
  CHECK(n.counts.insphere_zero == 0);
}

TEST_CASE("backend choice: parse and visit once", "[backend_choice]") {
  for (std::string_view name : kBackendNames) {
    const auto choice = parse_backend(name, 1e-9, true);
    REQUIRE(choice.has_value());
    CHECK(backend_name(*choice) == name);
    for (bool perturb : {false, true}) {
      const std::string got = visit_backend(*choice, perturb, [](const auto& b) {
        const Point3 a{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, -1};
        return std::string(b.name()) + ":" + std::to_string(b.orient3d(a, x, y, z));
      });
      CHECK(got == std::string(name) + ":1");
    }
  }
  CHECK_FALSE(parse_backend("fast").has_value());
  const auto eps = parse_backend("epsilon", 1e-9, true);
  CHECK(std::get<EpsilonPredicates>(*eps).eps == 1e-9);
  CHECK(std::get<EpsilonPredicates>(*eps).relative);
}

TEST_CASE("perturbed wrapper resolves a cospherical tie for every backend", "[backend_choice]") {
  const Point3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, -1}, e{1, 1, 0};
  for (std::string_view name : kBackendNames) {
    const auto choice = parse_backend(name);
    CHECK(visit_backend(*choice, false, [&](const auto& bk) { return bk.insphere(a, b, c, d, e); }) == 0);
    CHECK(visit_backend(*choice, true, [&](const auto& bk) { return bk.insphere(a, b, c, d, e); }) != 0);
  }
}
