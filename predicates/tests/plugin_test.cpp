#include <catch2/catch.hpp>

#include <random>
#include <string>

#include "families.hpp"
#include "predicates/backend_choice.hpp"
#include "predicates/plugin_predicates.hpp"

using namespace dtlab;
using namespace dtlab::test;

TEST_CASE("plug-in naive decides as the built-in naive, bit for bit", "[plugin]") {
  const PluginPredicates plugin{&load_plugin(DTLAB_PLUGIN_NAIVE)};
  CHECK(plugin.name() == "plugin-naive");
  const NaivePredicates naive;
  std::size_t calls = 0, zeros = 0;
  for (const Quad& q : hard_orient_inputs(7, 40)) {
    const int s = naive.orient3d(q[0], q[1], q[2], q[3]);
    zeros += s == 0;
    ++calls;
    REQUIRE(plugin.orient3d(q[0], q[1], q[2], q[3]) == s);
  }
  for (const Quint& q : hard_insphere_inputs(7, 40)) {
    const int s = naive.insphere(q[0], q[1], q[2], q[3], q[4]);
    zeros += s == 0;
    ++calls;
    REQUIRE(plugin.insphere(q[0], q[1], q[2], q[3], q[4]) == s);
  }
  std::mt19937_64 rng(3);
  for (int i = 0; i < 2000; ++i) {
    const Point3 a = random_point(rng), b = random_point(rng), c = random_point(rng), d = random_point(rng),
                 e = random_point(rng);
    REQUIRE(plugin.orient3d(a, b, c, d) == naive.orient3d(a, b, c, d));
    REQUIRE(plugin.insphere(a, b, c, d, e) == naive.insphere(a, b, c, d, e));
  }
  CHECK(calls > 1000);
  CHECK(zeros > 0);  // the hard cases do reach zero answers
}

TEST_CASE("plug-in exact agrees with GMP on every hard case", "[plugin]") {
  const PluginPredicates plugin{&load_plugin(DTLAB_PLUGIN_EXACT)};
  const ExactPredicates exact;
  for (const Quad& q : hard_orient_inputs(11, 20))
    REQUIRE(plugin.orient3d(q[0], q[1], q[2], q[3]) == exact.orient3d(q[0], q[1], q[2], q[3]));
  for (const Quint& q : hard_insphere_inputs(11, 20))
    REQUIRE(plugin.insphere(q[0], q[1], q[2], q[3], q[4]) == exact.insphere(q[0], q[1], q[2], q[3], q[4]));
  // The sign convention: d below the counter-clockwise abc, e inside.
  const Point3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, -1};
  CHECK(plugin.orient3d(a, b, c, d) == 1);
  CHECK(plugin.insphere(a, b, c, d, Point3{0.1, 0.1, -0.1}) == 1);
  CHECK(plugin.insphere(a, b, c, d, Point3{5, 5, 5}) == -1);
}

TEST_CASE("plug-in: parse_backend, with and without perturbation", "[plugin]") {
  const auto choice = parse_backend(std::string("plugin:") + DTLAB_PLUGIN_NAIVE);
  REQUIRE(choice.has_value());
  CHECK(backend_name(*choice) == "plugin-naive");
  const Point3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, -1}, e{1, 1, 0};  // e on the sphere
  CHECK(visit_backend(*choice, false, [&](const auto& p) { return p.insphere(a, b, c, d, e); }) == 0);
  CHECK(visit_backend(*choice, true, [&](const auto& p) { return p.insphere(a, b, c, d, e); }) != 0);
  // Loaded once: the same library object for the same path.
  CHECK(&load_plugin(DTLAB_PLUGIN_NAIVE) == &load_plugin(DTLAB_PLUGIN_NAIVE));
}

TEST_CASE("plug-in: a library without the symbols, or no library, is refused by name", "[plugin]") {
  CHECK_THROWS_WITH(load_plugin(DTLAB_PLUGIN_MISSING_SYMBOL), Catch::Contains("no symbol dtlab_insphere"));
  CHECK_THROWS_WITH(load_plugin("/nonexistent/plugin.so"), Catch::Contains("cannot load"));
  CHECK_THROWS_WITH(parse_backend("plugin:"), Catch::Contains("needs a path"));
  CHECK_THROWS_AS(parse_backend("plugin:/nonexistent/plugin.so"), std::invalid_argument);
}
