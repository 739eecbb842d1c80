// Mutation testing of the checker: valid outputs (ours, CGAL's, TetGen's) of several
// input families are mutated; each mutant's truth is decided without the checker
// (oracle/check/tests/mutation_truth.hpp: exact rationals, brute force, CGAL's own DT of
// the mutant's points), and the checker must agree on every mutant: no defective
// mutant passes, no valid one is flagged. The score printed here is the one quoted
// in oracle/README.md.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <random>
#include <set>

#include "kernel/build.hpp"
#include "oracle/check/check.hpp"
#include "oracle/check/facet_table.hpp"
#include "oracle/check/tests/check_helpers.hpp"
#include "oracle/check/tests/mutation_truth.hpp"
#include "oracle/check/tests/point_sets.hpp"
#include "oracle/peers/cgal_oracle.hpp"
#include "oracle/peers/tetgen_oracle.hpp"
#include "predicates/exact.hpp"

using namespace dtlab;

namespace {

struct Mesh {
  std::vector<Point3> points;
  std::vector<Tet> tets;
};

struct Mutant {
  std::string kind;
  Mesh mesh;
};

int orient(const std::vector<Point3>& P, const Tet& k) {
  return ExactPredicates{}.orient3d(P[k[0]], P[k[1]], P[k[2]], P[k[3]]);
}

// Positive orientation by swapping two vertices; false when flat.
bool make_positive(const std::vector<Point3>& P, Tet& k) {
  const int s = orient(P, k);
  if (s < 0) std::swap(k[0], k[1]);
  return s != 0;
}

std::array<std::uint32_t, 3> sorted_facet(const Tet& k, int f) {
  std::array<std::uint32_t, 3> v = {k[(f + 1) % 4], k[(f + 2) % 4], k[(f + 3) % 4]};
  std::sort(v.begin(), v.end());
  return v;
}

// 2-3 flips of convex interior facets: (a,b,c,d) + (a,b,c,e) -> three tets around d-e.
void flips23(const Mesh& m, std::mt19937_64& rng, int want, std::vector<Mutant>& out) {
  std::map<std::array<std::uint32_t, 3>, std::vector<std::pair<std::uint32_t, int>>> facets;
  for (std::uint32_t t = 0; t < m.tets.size(); ++t)
    for (int f = 0; f < 4; ++f) facets[sorted_facet(m.tets[t], f)].push_back({t, f});
  std::vector<std::array<std::uint32_t, 5>> convex;  // a b c d e, tets t1 t2 are looked up again
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  std::vector<std::size_t> cospherical;  // indices into convex
  const ExactPredicates ex;
  const auto& P = m.points;
  for (const auto& [key, users] : facets) {
    if (users.size() != 2) continue;
    const std::uint32_t d = m.tets[users[0].first][users[0].second], e = m.tets[users[1].first][users[1].second];
    const auto [a, b, c] = key;
    const int s1 = ex.orient3d(P[a], P[b], P[d], P[e]), s2 = ex.orient3d(P[b], P[c], P[d], P[e]),
              s3 = ex.orient3d(P[c], P[a], P[d], P[e]);
    if (s1 != 0 && s1 == s2 && s2 == s3) {
      convex.push_back({a, b, c, d, e});
      pairs.push_back({users[0].first, users[1].first});
      const Tet& k = m.tets[users[0].first];
      if (ex.insphere(P[k[0]], P[k[1]], P[k[2]], P[k[3]], P[e]) == 0) cospherical.push_back(convex.size() - 1);
    }
  }
  for (int i = 0; i < want && !convex.empty(); ++i) {
    // Half of them, where possible, on cospherical facets: those flips stay Delaunay.
    const std::size_t j = i % 2 == 0 && !cospherical.empty()
                              ? cospherical[std::uniform_int_distribution<std::size_t>(0, cospherical.size() - 1)(rng)]
                              : std::uniform_int_distribution<std::size_t>(0, convex.size() - 1)(rng);
    const auto [a, b, c, d, e] = convex[j];
    Mesh r = m;
    r.tets.erase(r.tets.begin() + std::max(pairs[j].first, pairs[j].second));
    r.tets.erase(r.tets.begin() + std::min(pairs[j].first, pairs[j].second));
    bool ok = true;
    for (Tet k : {Tet{d, e, a, b}, Tet{d, e, b, c}, Tet{d, e, c, a}}) {
      ok = ok && make_positive(P, k);
      r.tets.push_back(k);
    }
    if (ok) out.push_back({"flip-2-3", std::move(r)});
  }
}

// 3-2 flips: an edge d-e in exactly three tets (d,e,a,b), (d,e,b,c), (d,e,c,a) ->
// (a,b,c,d) + (a,b,c,e), whether or not d-e crosses triangle a b c.
void flips32(const Mesh& m, std::mt19937_64& rng, int want, std::vector<Mutant>& out) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> edges;
  for (std::uint32_t t = 0; t < m.tets.size(); ++t)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) edges[std::minmax(m.tets[t][i], m.tets[t][j])].push_back(t);
  std::vector<std::pair<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>>> deg3;
  std::vector<std::size_t> cospherical;  // the five points on one sphere
  const ExactPredicates ex;
  for (const auto& [e, ts] : edges)
    if (ts.size() == 3) {
      deg3.push_back({e, ts});
      std::set<std::uint32_t> all;
      for (auto t : ts) all.insert(m.tets[t].begin(), m.tets[t].end());
      const Tet& k = m.tets[ts[0]];
      for (auto v : all)
        if (std::find(k.begin(), k.end(), v) == k.end() &&
            ex.insphere(m.points[k[0]], m.points[k[1]], m.points[k[2]], m.points[k[3]], m.points[v]) == 0)
          cospherical.push_back(deg3.size() - 1);
    }
  for (int i = 0; i < want && !deg3.empty(); ++i) {
    const std::size_t pick =
        i % 2 == 0 && !cospherical.empty()
            ? cospherical[std::uniform_int_distribution<std::size_t>(0, cospherical.size() - 1)(rng)]
            : std::uniform_int_distribution<std::size_t>(0, deg3.size() - 1)(rng);
    const auto& [edge, ts] = deg3[pick];
    std::set<std::uint32_t> ring;
    for (auto t : ts)
      for (auto v : m.tets[t])
        if (v != edge.first && v != edge.second) ring.insert(v);
    if (ring.size() != 3) continue;
    const std::vector<std::uint32_t> abc(ring.begin(), ring.end());
    Mesh r;
    r.points = m.points;
    for (std::uint32_t t = 0; t < m.tets.size(); ++t)
      if (std::find(ts.begin(), ts.end(), t) == ts.end()) r.tets.push_back(m.tets[t]);
    bool ok = true;
    for (Tet k : {Tet{abc[0], abc[1], abc[2], edge.first}, Tet{abc[0], abc[1], abc[2], edge.second}}) {
      ok = ok && make_positive(r.points, k);
      r.tets.push_back(k);
    }
    if (ok) out.push_back({"flip-3-2", std::move(r)});
  }
}

std::vector<Mutant> mutate(const Mesh& m, std::mt19937_64& rng, int per_kind) {
  std::vector<Mutant> out;
  auto pick = [&](std::size_t size) { return std::uniform_int_distribution<std::size_t>(0, size - 1)(rng); };
  const std::size_t T = m.tets.size();
  for (int i = 0; i < per_kind; ++i) {
    Mesh d = m;
    d.tets.erase(d.tets.begin() + static_cast<std::ptrdiff_t>(pick(T)));
    out.push_back({"delete", std::move(d)});
    Mesh u = m;
    u.tets.push_back(m.tets[pick(T)]);
    out.push_back({"duplicate", std::move(u)});
    Mesh v = m;
    auto& k = v.tets[pick(T)];
    std::swap(k[2], k[3]);
    out.push_back({"invert", std::move(v)});
  }
  flips23(m, rng, per_kind, out);
  flips32(m, rng, per_kind, out);
  {
    // Relabel: a random permutation of the points, and an even permutation of
    // each tet's vertices (orientation kept).
    std::vector<std::uint32_t> perm(m.points.size());
    std::iota(perm.begin(), perm.end(), 0u);
    std::shuffle(perm.begin(), perm.end(), rng);
    Mesh r;
    r.points.resize(m.points.size());
    for (std::size_t i = 0; i < perm.size(); ++i) r.points[perm[i]] = m.points[i];
    for (const Tet& k : m.tets) r.tets.push_back({perm[k[1]], perm[k[2]], perm[k[0]], perm[k[3]]});
    out.push_back({"relabel", std::move(r)});
  }
  {
    // Move a vertex: by one ulp, and by a tenth of the extent.
    double lo = m.points[0].x, hi = lo;
    for (const auto& p : m.points) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
    for (int i = 0; i < per_kind; ++i) {
      Mesh a = m;
      auto& p = a.points[m.tets[pick(T)][0]];
      p.x = std::nextafter(p.x, p.x + 1);
      out.push_back({"move", std::move(a)});
      Mesh b = m;
      auto& q = b.points[m.tets[pick(T)][1]];
      std::uniform_real_distribution<double> u(-0.1, 0.1);
      q = {q.x + u(rng) * (hi - lo), q.y + u(rng) * (hi - lo), q.z + u(rng) * (hi - lo)};
      out.push_back({"move", std::move(b)});
    }
  }
  for (int e : {-350, -7, 350}) {
    Mesh s = m;
    for (auto& p : s.points) p = {std::ldexp(p.x, e), std::ldexp(p.y, e), std::ldexp(p.z, e)};
    out.push_back({"rescale", std::move(s)});
  }
  {
    // Double cover: a second copy of every tet over a copy of the points.
    Mesh c = m;
    const auto n = static_cast<std::uint32_t>(m.points.size());
    c.points.insert(c.points.end(), m.points.begin(), m.points.end());
    for (const Tet& k : m.tets) c.tets.push_back({k[0] + n, k[1] + n, k[2] + n, k[3] + n});
    out.push_back({"double-cover", std::move(c)});
  }
  return out;
}

struct Score {
  std::map<std::string, std::pair<int, int>> kinds;  // kind -> (valid mutants, invalid mutants)
  std::set<std::string> families, sources;
  int mutants = 0, agreed = 0;
};

void run(const std::string& family, const std::vector<Point3>& points, int per_kind, unsigned seed, Score& score) {
  struct Source {
    std::string name;
    std::optional<Mesh> mesh;
  };
  std::vector<Source> sources;
  {
    const BuildResult ours = build_delaunay(points, PredicateSpec{"adaptive", 0, false, true});
    REQUIRE_FALSE(ours.failure);
    sources.push_back({"dtlab", Mesh{ours.mesh.points, ours.mesh.tets}});
    const OracleRun cgal = cgal_delaunay(points);
    REQUIRE(cgal.mesh);
    sources.push_back({"cgal", Mesh{cgal.mesh->points, cgal.mesh->tets}});
    const OracleRun tetgen = tetgen_delaunay(points, {.binary = "tetgen", .timeout_s = 30});
    if (tetgen.mesh) sources.push_back({"tetgen", Mesh{tetgen.mesh->points, tetgen.mesh->tets}});
  }
  std::mt19937_64 rng(seed);
  for (const Source& src : sources) {
    Mutant original{"original", *src.mesh};
    std::vector<Mutant> all = mutate(*src.mesh, rng, per_kind);
    all.insert(all.begin(), std::move(original));
    for (const Mutant& mu : all) {
      // The reference DT of the mutant's own points.
      const OracleRun ref = cgal_delaunay(mu.mesh.points);
      REQUIRE(ref.mesh);
      const test::Truth truth = test::delaunay_truth(mu.mesh.points, mu.mesh.tets, ref.mesh->tets);
      Tetrahedralization t;
      t.points = mu.mesh.points;
      t.tets = mu.mesh.tets;
      const CheckReport r = test::check_both_ways(t);
      std::string defects;
      for (const Defect& d : r.defects) defects += std::string(defect_name(d.kind)) + ": " + d.detail + "\n";
      INFO(family << " / " << src.name << " / " << mu.kind << ": truth " << (truth.valid ? "valid" : truth.why)
                  << "\nchecker:\n"
                  << defects);
      CHECK(r.ok() == truth.valid);
      // Ours and CGAL's must be right; TetGen's plain DT is not always exactly
      // Delaunay on nearly degenerate input (its mutants are tested all the same).
      if (mu.kind == "original" && src.name != "tetgen") CHECK(truth.valid);
      if (mu.kind == "original" && !truth.valid)
        std::printf("note: %s's output on %s is not a Delaunay tetrahedralization (%s); checker agrees\n",
                    src.name.c_str(), family.c_str(), truth.why.c_str());
      ++score.mutants;
      score.agreed += r.ok() == truth.valid;
      auto& k = score.kinds[mu.kind];
      (truth.valid ? k.first : k.second)++;
    }
    score.sources.insert(src.name);
  }
  score.families.insert(family);
}

void report(const Score& s, const char* label) {
  std::printf("mutation score (%s): %d of %d mutants agreed; %zu families, sources:", label, s.agreed, s.mutants,
              s.families.size());
  for (const auto& n : s.sources) std::printf(" %s", n.c_str());
  std::printf("\n");
  for (const auto& [kind, vi] : s.kinds)
    std::printf("  %-12s %4d valid %4d invalid\n", kind.c_str(), vi.first, vi.second);
}

std::vector<Point3> with_duplicates(std::vector<Point3> p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; i += 7) p.push_back(p[i]);
  return p;
}

std::vector<Point3> near_lattice(int m, unsigned seed) {
  // A lattice with some coordinates nudged by one ulp: nearly cospherical sets.
  std::vector<Point3> p = test::lattice_points(m);
  std::mt19937_64 rng(seed);
  for (auto& q : p)
    if (rng() % 3 == 0) q.y = std::nextafter(q.y, 10.0);
  return p;
}

}  // namespace

TEST_CASE("mutation testing: the checker agrees with an independent truth on every mutant", "[check][mutation]") {
  Score score;
  std::vector<Point3> sphere_center = test::sphere_points(27);
  sphere_center.push_back({0, 0, 0});
  run("uniform", test::uniform_points(40, 3), 2, 1, score);
  run("uniform+duplicates", with_duplicates(test::uniform_points(30, 4)), 2, 2, score);
  run("lattice", test::lattice_points(3), 2, 3, score);
  run("near-lattice", near_lattice(3, 5), 2, 4, score);
  run("sphere+center", sphere_center, 2, 5, score);
  run("sphere", test::sphere_points(27), 2, 6, score);  // one Delaunay cell: flips stay valid
  report(score, "make test");
  CHECK(score.agreed == score.mutants);
  CHECK(score.kinds.size() == 10);  // original + 9 mutation kinds
}

TEST_CASE("mutation testing, larger inputs and more mutants", "[check][mutation][slow]") {
  Score score;
  for (unsigned s = 0; s < 4; ++s) {
    run("uniform", test::uniform_points(150, 100 + s), 6, 10 + s, score);
    run("uniform+duplicates", with_duplicates(test::uniform_points(100, 200 + s)), 6, 20 + s, score);
    run("near-lattice", near_lattice(4, 300 + s), 6, 30 + s, score);
  }
  run("lattice", test::lattice_points(4), 6, 40, score);
  run("sphere", test::sphere_points(50), 6, 41, score);
  report(score, "slow");
  CHECK(score.agreed == score.mutants);
}
