#include <catch2/catch.hpp>

#include <iostream>

#include "families.hpp"
#include "predicates/epsilon.hpp"
#include "predicates/exact.hpp"
#include "predicates/naive.hpp"

using namespace dtlab;
using namespace dtlab::test;

namespace {

struct Tally {
  long orient_wrong = 0, orient_total = 0, insphere_wrong = 0, insphere_total = 0;
};

template <class B>
Tally tally(const B& b, const std::vector<Quad>& quads, const std::vector<Quint>& quints) {
  const ExactPredicates ex;
  Tally t;
  for (const Quad& q : quads) {
    ++t.orient_total;
    t.orient_wrong += b.orient3d(q[0], q[1], q[2], q[3]) != ex.orient3d(q[0], q[1], q[2], q[3]);
  }
  for (const Quint& q : quints) {
    ++t.insphere_total;
    t.insphere_wrong +=
        b.insphere(q[0], q[1], q[2], q[3], q[4]) != ex.insphere(q[0], q[1], q[2], q[3], q[4]);
  }
  return t;
}

void print(const char* name, const Tally& t) {
  std::cout << "  " << name << ": orient3d wrong " << t.orient_wrong << " / " << t.orient_total
            << ", insphere wrong " << t.insphere_wrong << " / " << t.insphere_total << "\n";
}

}  // namespace

TEST_CASE("naive and epsilon disagree with exact on the hard families", "[naive][epsilon]") {
  const auto quads = hard_orient_inputs(21, 2000);
  const auto quints = hard_insphere_inputs(22, 2000);
  std::cout << "disagreements with exact on the hard families:\n";
  const Tally n = tally(NaivePredicates{}, quads, quints);
  const Tally ea = tally(EpsilonPredicates{1e-12, false}, quads, quints);
  const Tally er = tally(EpsilonPredicates{1e-12, true}, quads, quints);
  print("naive", n);
  print("epsilon abs 1e-12", ea);
  print("epsilon rel 1e-12", er);
  CHECK(n.orient_wrong > 0);
  CHECK(n.insphere_wrong > 0);
  CHECK(ea.orient_wrong > 0);
  CHECK(ea.insphere_wrong > 0);
  CHECK(er.orient_wrong > 0);
  CHECK(er.insphere_wrong > 0);
}

TEST_CASE("naive and epsilon on random input", "[naive][epsilon]") {
  std::mt19937_64 rng(23);
  std::vector<Quad> quads;
  std::vector<Quint> quints;
  for (int i = 0; i < 100000; ++i) {
    quads.push_back({random_point(rng), random_point(rng), random_point(rng), random_point(rng)});
    quints.push_back({random_point(rng), random_point(rng), random_point(rng), random_point(rng),
                      random_point(rng)});
  }
  std::cout << "disagreements with exact on random input:\n";
  const Tally n = tally(NaivePredicates{}, quads, quints);
  const Tally er = tally(EpsilonPredicates{1e-12, true}, quads, quints);
  print("naive", n);
  print("epsilon rel 1e-12", er);
  // Random points are far from degenerate: the plain determinant is (almost) always right.
  CHECK(n.orient_wrong + n.insphere_wrong <= 2);
  CHECK(er.orient_wrong + er.insphere_wrong <= 2);
}

TEST_CASE("epsilon: the band answers zero, absolute and relative", "[epsilon]") {
  const Point3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  const EpsilonPredicates abs_eps{1e-6, false}, rel_eps{1e-6, true};
  CHECK(abs_eps.orient3d(a, b, c, Point3{0.2, 0.2, 1e-7}) == 0);
  CHECK(abs_eps.orient3d(a, b, c, Point3{0.2, 0.2, 1e-5}) == -1);
  // Relative: the same configuration scaled by 1e3 keeps its answer.
  auto s = [](Point3 p) { return Point3{p.x * 1e3, p.y * 1e3, p.z * 1e3}; };
  CHECK(rel_eps.orient3d(s(a), s(b), s(c), s(Point3{0.2, 0.2, 1e-7})) == 0);
  CHECK(rel_eps.orient3d(s(a), s(b), s(c), s(Point3{0.2, 0.2, 1e-5})) == -1);
  CHECK(abs_eps.orient3d(s(a), s(b), s(c), s(Point3{0.2, 0.2, 1e-7})) == -1);
  const Point3 d{0, 0, -1};
  CHECK(rel_eps.insphere(a, b, c, d, Point3{1, 1, 1e-8}) == 0);
  CHECK(rel_eps.insphere(a, b, c, d, Point3{0.25, 0.25, -0.25}) == 1);
}
