#include "experiments/conformance.hpp"

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "experiments/conformance_cases.hpp"
#include "fuzz/campaign.hpp"
#include "fuzz/case_seed.hpp"
#include "fuzz/families.hpp"
#include "fuzz/outcome.hpp"
#include "predicates/backend_choice.hpp"

namespace dtlab::experiments {
namespace {

void count(SignTally& t, int got, int want) {
  ++t.cases;
  t.exact_zeros += want == 0;
  if (got == want) return;
  if (want == 0) ++t.missed_zero;
  else if (got == 0) ++t.false_zero;
  else ++t.flipped;
}

// Every case of every class through the backend and through GMP.
std::vector<SignTally> sign_tallies(const BackendChoice& choice, const ConformanceOptions& o) {
  const ExactPredicates exact;
  std::vector<SignTally> out;
  for (const PredicateCases& c : conformance_cases(o.cases, o.seed)) {
    SignTally orient, insphere;
    orient.predicate = "orient3d", insphere.predicate = "insphere";
    orient.case_class = insphere.case_class = c.case_class;
    std::visit(
        [&](const auto& b) {
          for (const auto& q : c.orient) count(orient, b.orient3d(q[0], q[1], q[2], q[3]), exact.orient3d(q[0], q[1], q[2], q[3]));
          for (const auto& q : c.insphere)
            count(insphere, b.insphere(q[0], q[1], q[2], q[3], q[4]), exact.insphere(q[0], q[1], q[2], q[3], q[4]));
        },
        choice);
    if (orient.cases) out.push_back(orient);
    if (insphere.cases) out.push_back(insphere);
  }
  return out;
}

// Whole builds of every fuzz family, each judged by the exact checker (fuzz::run_case).
std::vector<BuildTally> build_tallies(const ConformanceOptions& o) {
  std::vector<BuildTally> out;
  for (const fuzz::Family& f : fuzz::families()) {
    BuildTally t;
    t.family = f.name;
    for (std::size_t i = 0; i < o.builds; ++i) {
      const std::uint64_t seed = fuzz::case_seed(o.seed, f.name, i);
      const auto points = f.generate(o.points, seed);
      BuildOptions build;
      build.seed = seed;
      const fuzz::CaseRun run = fuzz::run_case(points, o.predicates, build);
      ++t.builds;
      if (run.ok()) ++t.valid;
      else ++t.failures[run.outcome];
    }
    out.push_back(t);
  }
  return out;
}

}  // namespace

std::size_t ConformanceReport::sign_errors() const {
  std::size_t n = 0;
  for (const auto& s : signs) n += s.errors();
  return n;
}

std::size_t ConformanceReport::failed_builds() const {
  std::size_t n = 0;
  for (const auto& b : builds) n += b.builds - b.valid;
  return n;
}

ConformanceReport run_conformance(const ConformanceOptions& o) {
  const auto choice = parse_backend(o.predicates.backend, o.predicates.eps, o.predicates.relative_eps);
  if (!choice) throw std::invalid_argument("unknown predicates '" + o.predicates.backend + "'");
  ConformanceReport r;
  r.backend = fuzz::backend_label(o.predicates);
  r.signs = sign_tallies(*choice, o);
  r.builds = build_tallies(o);
  return r;
}

std::string conformance_table(const ConformanceReport& r) {
  std::ostringstream o;
  char line[256];
  o << "predicates " << r.backend << " against GMP\n";
  std::snprintf(line, sizeof line, "  %-9s %-26s %6s %7s %8s %10s %11s\n", "predicate", "class", "cases", "errors",
                "flipped", "false-zero", "missed-zero");
  o << line;
  for (const auto& s : r.signs) {
    std::snprintf(line, sizeof line, "  %-9s %-26s %6zu %7zu %8zu %10zu %11zu\n", s.predicate.c_str(),
                  s.case_class.c_str(), s.cases, s.errors(), s.flipped, s.false_zero, s.missed_zero);
    o << line;
  }
  o << "whole builds (" << r.backend << "), judged by the exact checker\n";
  std::snprintf(line, sizeof line, "  %-18s %6s %6s %6s  %s\n", "family", "builds", "valid", "failed", "failures");
  o << line;
  for (const auto& b : r.builds) {
    std::string kinds;
    for (const auto& [k, n] : b.failures) kinds += (kinds.empty() ? "" : ", ") + k + " " + std::to_string(n);
    std::snprintf(line, sizeof line, "  %-18s %6zu %6zu %6zu  %s\n", b.family.c_str(), b.builds, b.valid,
                  b.builds - b.valid, kinds.c_str());
    o << line;
  }
  o << (r.passed() ? "PASSED" : "FAILED") << ": " << r.sign_errors() << " sign errors, " << r.failed_builds()
    << " failed builds\n";
  return o.str();
}

nlohmann::json to_json(const ConformanceReport& r) {
  nlohmann::json signs = nlohmann::json::array(), builds = nlohmann::json::array();
  for (const auto& s : r.signs)
    signs.push_back({{"predicate", s.predicate}, {"class", s.case_class}, {"cases", s.cases}, {"errors", s.errors()},
                     {"flipped", s.flipped}, {"false_zero", s.false_zero}, {"missed_zero", s.missed_zero},
                     {"exact_zeros", s.exact_zeros}});
  for (const auto& b : r.builds)
    builds.push_back({{"family", b.family}, {"builds", b.builds}, {"valid", b.valid}, {"failures", b.failures}});
  return {{"backend", r.backend}, {"passed", r.passed()}, {"sign_errors", r.sign_errors()},
          {"failed_builds", r.failed_builds()}, {"signs", signs}, {"builds", builds}};
}

}  // namespace dtlab::experiments
