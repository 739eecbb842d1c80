// Orchestration and report of `dtlab experiment thesis-failures`.
#include "experiments/thesis_failures.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "kernel/output_file.hpp"
#include "experiments/report.hpp"
#include "experiments/thesis_parts.hpp"

namespace dtlab::experiments {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const std::vector<std::string> kHardFamilies = {"clustered", "near_degenerate", "ulp_jitter", "kettner_grid",
                                                "torus-rays"};
bool is_hard(const std::string& f) { return std::count(kHardFamilies.begin(), kHardFamilies.end(), f) > 0; }

std::string pct(double x) { return fmt(x >= 0.1 ? "%.0f%%" : "%.1f%%", 100 * x); }

// The failure rates' facts: the naive backend's failures on the hard families at the
// smallest and largest n, and the robust backends' failed cases.
void rate_facts(const json& rates, json& f) {
  const std::size_t nmax = rates["sizes"].back().get<std::size_t>();
  const std::size_t nmin = rates["sizes"].front().get<std::size_t>();
  int hard_cases = 0, hard_failed = 0, hard_cases_min = 0, hard_failed_min = 0;
  std::map<std::string, int> naive_kind, robust_failed, robust_cases;
  for (const auto& c : rates["cells"]) {
    const std::string b = c["backend"];
    if (b == "naive") {
      for (const char* k : {"failed", "crash", "overlap_inverted", "missing_point", "non_delaunay"})
        naive_kind[k] += c[k].get<int>();
      if (is_hard(c["family"]) && c["n"].get<std::size_t>() == nmax) {
        hard_cases += c["cases"].get<int>();
        hard_failed += c["failed"].get<int>();
      }
      if (is_hard(c["family"]) && c["n"].get<std::size_t>() == nmin) {
        hard_cases_min += c["cases"].get<int>();
        hard_failed_min += c["failed"].get<int>();
      }
    }
    if (b == "adaptive+sos" || b == "exact+sos") {
      robust_failed[b] += c["failed"].get<int>();
      robust_cases[b] += c["cases"].get<int>();
    }
  }
  f["naive_failure_rate_hard_at_max_n"] = hard_cases ? double(hard_failed) / hard_cases : 0.0;
  f["naive_hard_at_max_n"] = {{"failed", hard_failed}, {"cases", hard_cases}};
  f["naive_hard_at_min_n"] = {{"failed", hard_failed_min}, {"cases", hard_cases_min}};
  f["min_n"] = nmin;
  f["robust_cases"] = robust_cases;
  f["max_n"] = nmax;
  f["naive_cases_with"] = naive_kind;
  f["robust_failed_cases"] = robust_failed;
}

// The cost runs' facts: defects of the robust backends, timings on uniform points, the
// share of adaptive calls past the filter, epsilon's defects.
void cost_facts(const json& cost, json& f) {
  int robust_defects = 0;
  for (const auto& c : cost["cells"])
    if ((c["backend"] == "adaptive+sos" || c["backend"] == "exact+sos"))
      robust_defects += c["defects"].get<int>() + (c["failure"] != "" ? 1 : 0);
  f["robust_defects_in_cost_runs"] = robust_defects;
  std::map<std::string, double> uniform_time;  // the largest n (the last cells)
  for (const auto& c : cost["cells"])
    if (c["source"] == "uniform") {
      uniform_time[c["backend"]] = c["median_s"];
      f["uniform_timing"][c["backend"].get<std::string>()] = {
          {"median", c["median_s"]}, {"min", c["min_s"]}, {"max", c["max_s"]}, {"runs", c["runs"]}, {"n", c["n"]}};
    }
  // the share of adaptive calls past the semi-static filter, largest n of each source
  for (const auto& c : cost["cells"])
    if (c["backend"] == "adaptive+sos") {
      std::uint64_t all = 0, filter = 0;
      for (const auto& [k, v] : c["stages"].items()) {
        all += v.get<std::uint64_t>();
        if (k.find("semistatic") != std::string::npos) filter += v.get<std::uint64_t>();
      }
      f["adaptive_past_filter"][c["source"].get<std::string>()] = {
          {"n", c["n"]}, {"share", all ? 1.0 - double(filter) / double(all) : 0.0}};
    }
  if (uniform_time["naive"] > 0) {
    f["adaptive_over_naive_uniform"] = uniform_time["adaptive+sos"] / uniform_time["naive"];
    f["exact_over_naive_uniform"] = uniform_time["exact+sos"] / uniform_time["naive"];
  }
  for (const auto& c : cost["cells"])
    if (c["backend"] == "epsilon" && c["source"] == "uniform") {
      f["epsilon_uniform_defects"] = c["defects"];  // the last one: the largest n
      f["epsilon_uniform_n"] = c["n"];
    }
}

// Epsilon's facts: the best eps of each mode, failure rate pooled over the families.
void epsilon_facts(const json& eps, json& f) {
  std::map<std::pair<std::string, double>, std::pair<int, int>> pooled;
  for (const auto& c : eps["cells"]) {
    auto& p = pooled[{c["mode"].get<std::string>(), c["eps"].get<double>()}];
    p.first += c["failed"].get<int>();
    p.second += c["cases"].get<int>();
  }
  for (const char* mode : {"naive", "absolute", "relative"}) {
    double best = 2, best_eps = 0;
    int failed = 0, cases = 0;
    for (const auto& [key, v] : pooled)
      if (key.first == mode && double(v.first) / v.second < best) {
        best = double(v.first) / v.second;
        best_eps = key.second;
        failed = v.first;
        cases = v.second;
      }
    f["epsilon_best_failure_rate"][mode] = {{"rate", best}, {"eps", best_eps}, {"failed", failed}, {"cases", cases}};
  }
}

// The big tetrahedron's facts: cases with missing tets at the smallest factor that
// holds every point, and the factor each case needed.
void bigtet_facts(const json& bigtet, json& f) {
  int small_cases = 0, small_missing = 0;
  double smallest = bigtet["factors"][0];
  for (const auto& c : bigtet["cells"])
    if (c["factor"].get<double>() == smallest) {
      ++small_cases;
      if (c["missing"].get<int>() > 0 || c["failure"] != "") ++small_missing;
    }
  f["bigtet_smallest_factor"] = smallest;
  f["bigtet_cases_wrong_at_smallest_factor"] = small_missing;
  f["bigtet_cases"] = small_cases;
  double need_max = 0;
  int never = 0;
  for (const auto& r : bigtet["required"])
    if (r["required_factor"].is_null()) ++never;
    else need_max = std::max(need_max, r["required_factor"].get<double>());
  f["bigtet_required_factor_max"] = need_max;
  for (const auto& r : bigtet["required"])
    if (!r["required_factor"].is_null() && r["required_factor"].get<double>() == need_max) {
      f["bigtet_hardest_family"] = r["family"];
      f["bigtet_hardest_n"] = r["n"];
      break;
    }
  f["bigtet_cases_wrong_at_every_factor"] = never;
}

// The sampling facts: points outside the mesh by method and hole frequency.
void sampling_facts(const json& sampling, json& f) {
  for (const auto& c : sampling["cells"]) {
    f["outside_fraction"][c["method"].get<std::string>()][std::to_string(c["removed_every"].get<int>())] =
        c["outside_fraction"];
    f["outside_count"][c["method"].get<std::string>()][std::to_string(c["removed_every"].get<int>())] = {
        {"outside", c["outside"]}, {"points", c["points"]}};
  }
}

json compute_facts(const json& rates, const json& eps, const json& bigtet, const json& cost, const json& sampling,
                   const json& overlap) {
  json f;
  rate_facts(rates, f);
  cost_facts(cost, f);
  epsilon_facts(eps, f);
  bigtet_facts(bigtet, f);
  sampling_facts(sampling, f);
  f["overlap_case_points"] = overlap.is_null() ? 0 : overlap["points"].size();
  f["epsilon_n"] = eps["n"];
  return f;
}

std::string rates_markdown(const json& rates) {
  std::ostringstream o;
  const auto& sizes = rates["sizes"];
  std::vector<std::string> head = {"backend / family"};
  for (const auto& n : sizes) head.push_back("n=" + std::to_string(n.get<std::size_t>()));
  o << "Failure rate per cell: percent, [95% Wilson interval], (failed/cases).\n\n";
  o << table_row(head) << table_rule(head.size());
  std::map<std::pair<std::string, std::string>, std::map<std::size_t, json>> grid;
  for (const auto& c : rates["cells"]) grid[{c["backend"], c["family"]}][c["n"]] = c;
  for (const std::string& b : rates["labels"].get<std::vector<std::string>>())
    for (const auto& fam : rates["families"]) {
      std::vector<std::string> row = {b + " / " + fam.get<std::string>()};
      for (const auto& n : sizes) {
        const json& c = grid[{b, fam}][n.get<std::size_t>()];
        row.push_back(rate_cell(c["failed"].get<std::size_t>(), c["cases"].get<std::size_t>()));
      }
      o << table_row(row);
    }
  o << "\n";
  // what went wrong, naive, largest n
  const std::size_t nmax = sizes.back();
  o << "Naive at n = " << nmax << ", cases per kind of failure (a case may show several):\n\n";
  o << table_row({"family", "cases", "failed", "crash (walk/flip, contained)", "overlapping/inverted", "points missing (stopped build or missing-point)",
                  "non-Delaunay", "outcomes"})
    << table_rule(8);
  for (const auto& fam : rates["families"]) {
    const json& c = grid[{"naive", fam}][nmax];
    std::string outs;
    for (const auto& [k, v] : c["outcomes"].items()) outs += (outs.empty() ? "" : ", ") + k + " " + v.dump();
    o << table_row({fam, c["cases"].dump(), c["failed"].dump(), c["crash"].dump(), c["overlap_inverted"].dump(),
                    c["missing_point"].dump(), c["non_delaunay"].dump(), outs});
  }
  o << "\n";
  return o.str();
}

std::string eps_markdown(const json& eps) {
  std::ostringstream o;
  std::map<std::pair<std::string, double>, std::pair<int, int>> pooled;
  std::vector<double> values;
  for (const auto& c : eps["cells"]) {
    auto& p = pooled[{c["mode"].get<std::string>(), c["eps"].get<double>()}];
    p.first += c["failed"].get<int>();
    p.second += c["cases"].get<int>();
  }
  std::vector<std::string> head = {"mode"};
  for (const auto& e : eps["eps"]) head.push_back(fmt("%.0e", e.get<double>()));
  const auto& naive = pooled[{"naive", 0.0}];
  o << "Failure rate pooled over the families, [95% Wilson interval], (failed/cases) (naive: "
    << rate_cell(naive.first, naive.second) << "):\n\n" << table_row(head) << table_rule(head.size());
  for (const char* mode : {"absolute", "relative"}) {
    std::vector<std::string> row = {mode};
    for (const auto& e : eps["eps"]) {
      const auto& p = pooled[{mode, e.get<double>()}];
      row.push_back(rate_cell(p.first, p.second));
    }
    o << table_row(row);
  }
  o << "\n";
  return o.str();
}

std::string bigtet_markdown(const json& bigtet) {
  std::ostringstream o;
  const std::vector<double> shown = {1, 2, 10, 100, 1e4, 1e6, 1e8, 1e12};
  std::vector<std::string> head = {"family", "n"};
  for (double f : shown) head.push_back("factor " + fmt("%g", f));
  head.push_back("required factor (median / max)");
  o << "Share of the correct (infinite-vertex) tets missing from the bigtet result, mean over cases:\n\n"
    << table_row(head) << table_rule(head.size(), 2);
  for (const auto& fam : bigtet["families"])
    for (const auto& n : bigtet["sizes"]) {
      std::vector<std::string> row = {fam, n.dump()};
      for (double f : shown) {
        double sum = 0;
        int k = 0;
        for (const auto& c : bigtet["cells"])
          if (c["family"] == fam && c["n"] == n && c["factor"].get<double>() == f) {
            sum += c["failure"] != "" ? 1.0 : c["missing"].get<double>() / std::max(1.0, c["reference_tets"].get<double>());
            ++k;
          }
        row.push_back(k ? pct(sum / k) : "");
      }
      std::vector<double> need;
      int never = 0;
      for (const auto& r : bigtet["required"])
        if (r["family"] == fam && r["n"] == n) {
          if (r["required_factor"].is_null()) ++never;
          else need.push_back(r["required_factor"]);
        }
      std::sort(need.begin(), need.end());
      std::string cell = need.empty() ? "-" : fmt("%g", need[need.size() / 2]) + " / " + fmt("%g", need.back());
      if (never) cell += " (" + std::to_string(never) + " never)";
      row.push_back(cell);
      o << table_row(row);
    }
  o << "\n";
  return o.str();
}

std::string cost_markdown(const json& cost) {
  std::ostringstream o;
  o << table_row({"points", "n", "backend", "median s", "min s", "max s", "x naive", "defects", "build failure",
                  "orient3d calls", "insphere calls"})
    << table_rule(11, 1);
  std::map<std::pair<std::string, std::size_t>, double> naive;
  for (const auto& c : cost["cells"])
    if (c["backend"] == "naive") naive[{c["source"], c["n"]}] = c["median_s"];
  for (const auto& c : cost["cells"]) {
    const double base = naive[{c["source"], c["n"]}];
    o << table_row({c["source"], c["n"].dump(), c["backend"], fmt("%.4f", c["median_s"]), fmt("%.4f", c["min_s"]),
                    fmt("%.4f", c["max_s"]), base > 0 ? fmt("%.2f", c["median_s"].get<double>() / base) : "",
                    c["defects"].dump(), c["failure"].get<std::string>().empty() ? "-" : c["failure"].get<std::string>(),
                    c["orient3d_calls"].dump(), c["insphere_calls"].dump()});
  }
  o << "\nAdaptive stages (share of the calls each stage decided; `filter` is the semi-static filter, "
       "A..D Shewchuk's stages, `exact` the GMP fallback):\n\n";
  o << table_row({"points", "n", "stage calls"}) << table_rule(3, 2);
  for (const auto& c : cost["cells"]) {
    if (c["backend"] != "adaptive+sos") continue;
    std::uint64_t o3 = 0, is = 0;
    for (const auto& [k, v] : c["stages"].items()) (k.rfind("orient3d", 0) == 0 ? o3 : is) += v.get<std::uint64_t>();
    std::string s;
    for (const auto& [k, v] : c["stages"].items()) {
      const double total = double(k.rfind("orient3d", 0) == 0 ? o3 : is);
      s += (s.empty() ? "" : ", ") + k + " " + v.dump() + " (" + fmt("%.3g%%", 100.0 * v.get<double>() / total) + ")";
    }
    o << table_row({c["source"], c["n"].dump(), s});
  }
  o << "\n";
  return o.str();
}

std::string sampling_markdown(const json& s) {
  std::ostringstream o;
  o << "Share of samples outside the solid, [95% Wilson interval], (outside/points):\n\n";
  o << table_row({"faces removed", "rays outside", "sdf outside", "winding outside"}) << table_rule(4);
  std::map<int, std::map<std::string, json>> g;
  std::map<int, double> frac;
  for (const auto& c : s["cells"]) {
    g[c["removed_every"]][c["method"]] = c;
    frac[c["removed_every"]] = c["removed_fraction"];
  }
  for (int k : {0, 100, 50, 20, 7}) {
    if (!g.count(k)) continue;
    std::vector<std::string> row = {k ? pct(frac[k]) + " (every " + std::to_string(k) + "th)" : "none (closed)"};
    for (const char* m : {"rays", "sdf", "winding"}) {
      const json& c = g[k][m];
      row.push_back(rate_cell(c["outside"].get<std::size_t>(), c["points"].get<std::size_t>()));
    }
    o << table_row(row);
  }
  o << "\n";
  return o.str();
}

std::string overlap_markdown(const json& c) {
  if (c.is_null()) return "No small naive failure with overlapping tets was found in the searched cases.\n\n";
  std::ostringstream o;
  o << "Found in family `" << c["family"].get<std::string>() << "` (case seed " << c["case_seed"] << ", "
    << c["original_points"] << " points), shrunk by delta debugging (" << c["shrink_tests"]
    << " builds) to **" << c["points"].size() << " points**: the naive build returns " << c["naive_tets"].size()
    << " tets" << (c["naive_failure"] != "" ? " and stops with `" + c["naive_failure"].get<std::string>() + "`" : "")
    << ", the exact one " << c["exact_tets"].size() << ". Defects found by the exact checker: ";
  std::string s;
  for (const auto& [k, v] : c["defect_counts"].items()) s += (s.empty() ? "" : ", ") + k + " " + v.dump();
  o << s << ". An inverted tet (exact orient3d < 0) lies on the wrong side of its own facets: the space it "
       "covers is covered by its neighbours too, so the tets overlap (the thesis's Figure 5.31). Points (bit exact, replay with `dtlab tetra data/overlap_case.xyz --predicates naive --perturb none`): "
    << "`data/overlap_case.xyz`; the tets and witnesses: `data/overlap_case.json`.\n\n";
  return o.str();
}

// The title and what the report reproduces (a quick run says so).
void intro_markdown(std::ostream& o, const json& rates, bool quick) {
  o << "# dtlab: the thesis's robustness failures, reproduced\n\n";
  o << "Chapter 5 of the thesis reports, for its incremental flip-based Delaunay tetrahedralization with "
       "plain floating point: overlapping tetrahedra, points missing from the result, crashes that got worse "
       "as the number of points grew, a tolerance (epsilon) that did not help, a big enclosing tetrahedron, "
       "and ray-intersection sampling that put points outside concave meshes. Each is reproduced here with "
       "dtlab's one inserter, switching only the predicate backend, the boundary method or the sampler, and "
       "every result is judged by the exact checker (`oracle/check/check.hpp`).";
  if (quick)
    o << " **Quick run** (`--quick`): " << rates["cases"] << " cases per cell and fewer sizes, so the intervals "
      << "are wide; the full run uses 64 cases per cell. Cite the full run, not this one.";
}

// Finding: naive floating point fails, more often as n grows.
void naive_finding(std::ostream& o, const json& facts) {
  const auto& nk = facts["naive_cases_with"];
  const auto& hard_max = facts["naive_hard_at_max_n"];
  const auto& hard_min = facts["naive_hard_at_min_n"];
  o << "- **Naive floating point fails, and more often as n grows.** Pooled over the hard families ("
    << "clustered, near_degenerate, ulp_jitter, kettner_grid, torus-rays), naive builds are wrong in "
    << rate_cell(hard_min["failed"], hard_min["cases"]) << " of the cases at n = " << facts["min_n"] << " and "
    << rate_cell(hard_max["failed"], hard_max["cases"]) << " at n = " << facts["max_n"] << ". "
    << "Over all " << nk.value("failed", 0) << " failed naive cases: " << nk.value("crash", 0)
    << " stopped in a walk or flip loop (the thesis's crashes, here bounded and named), " << nk.value("overlap_inverted", 0)
    << " had overlapping or inverted tets, " << nk.value("missing_point", 0) << " left points out of the result, "
    << nk.value("non_delaunay", 0) << " had non-Delaunay facets (a case may count in several; a build that stops "
       "is not checked further, so these are lower bounds).\n";
}

// Finding: the tolerance does not fix it.
void epsilon_finding(std::ostream& o, const json& facts) {
  const auto& be = facts["epsilon_best_failure_rate"];
  o << "- **The tolerance does not fix it.** Pooled over its families at n = " << facts.value("epsilon_n", 0)
    << ", the best absolute eps (" << fmt("%.0e", be["absolute"]["eps"]) << ") fails "
    << rate_cell(be["absolute"]["failed"], be["absolute"]["cases"]) << ", the best relative eps ("
    << fmt("%.0e", be["relative"]["eps"]) << ") " << rate_cell(be["relative"]["failed"], be["relative"]["cases"])
    << "; naive: " << rate_cell(be["naive"]["failed"], be["naive"]["cases"]) << ".";
  if (facts.contains("epsilon_uniform_defects") && facts["epsilon_uniform_defects"].get<int>() > 0)
    o << " The absolute band 1e-12 also breaks an input that naive builds correctly: uniform points, n = "
      << facts["epsilon_uniform_n"] << ", " << facts["epsilon_uniform_defects"] << " defects (section 4).";
  o << "\n";
}

// Finding: the big tetrahedron drops hull tets unless it is huge.
void bigtet_finding(std::ostream& o, const json& facts) {
  o << "- **A big enclosing tetrahedron drops hull tets unless it is huge.** At factor "
    << facts["bigtet_smallest_factor"] << ", the result differs from the true DT on "
    << rate_cell(facts["bigtet_cases_wrong_at_smallest_factor"], facts["bigtet_cases"])
    << " of the inputs; the largest factor an input needed was " << fmt("%g", facts["bigtet_required_factor_max"]);
  if (facts.contains("bigtet_hardest_family"))
    o << " (`" << facts["bigtet_hardest_family"].get<std::string>() << "`, n = " << facts["bigtet_hardest_n"] << ")";
  if (facts["bigtet_cases_wrong_at_every_factor"].get<int>() > 0)
    o << ", and " << facts["bigtet_cases_wrong_at_every_factor"] << " inputs were wrong even at 1e12";
  o << " (section 3 lists the factor each family needed).\n";
}

// Finding: adaptive and exact predicates have no defects, and what they cost.
void robust_finding(std::ostream& o, const json& facts) {
  int robust = facts["robust_defects_in_cost_runs"].get<int>();
  std::size_t robust_total = 0;
  for (const auto& [k, v] : facts["robust_failed_cases"].items()) robust += v.get<int>();
  for (const auto& [k, v] : facts["robust_cases"].items()) robust_total += v.get<std::size_t>();
  o << "- **Adaptive and exact predicates: " << (robust == 0 ? "zero defects" : std::to_string(robust) + " DEFECTS (a regression)")
    << "** in the cases of section 1 (failure rate " << rate_cell(static_cast<std::size_t>(robust), robust_total)
    << " over both backends) and in every build of section 4.";
  const auto& ut = facts["uniform_timing"];
  if (ut.contains("naive") && ut.contains("adaptive+sos") && ut.contains("exact+sos")) {
    const auto timing = [&](const char* b) {
      const auto& t = ut[b];
      return Timing{t["median"].get<double>(), t["min"].get<double>(), t["max"].get<double>(), t["runs"].get<int>()};
    };
    o << " Build time on uniform points (n = " << ut["naive"]["n"] << "), adaptive vs naive: "
      << timing_claim(timing("adaptive+sos"), timing("naive")) << "; exact vs naive: "
      << timing_claim(timing("exact+sos"), timing("naive")) << ".";
  }
  if (facts.contains("adaptive_past_filter")) {
    const auto& pf = facts["adaptive_past_filter"];
    o << " Share of adaptive predicate calls the semi-static filter could not decide:";
    std::string sep = " ";
    for (const auto& [src, v] : pf.items()) {
      o << sep << "`" << src << "` (n = " << v["n"] << ") " << fmt("%.3g%%", 100 * v["share"].get<double>());
      sep = ", ";
    }
    o << ".";
  }
  o << "\n";
}

// Finding: ray sampling puts points outside a mesh with holes.
void sampling_finding(std::ostream& o, const json& facts) {
  const auto& oc = facts["outside_count"];
  const auto outside = [&](const char* m, const char* k) {
    return rate_cell(oc[m][k]["outside"].get<std::size_t>(), oc[m][k]["points"].get<std::size_t>());
  };
  o << "- **Ray-intersection sampling puts points outside a mesh with holes.** With every 20th torus face removed, "
    << "the share of samples outside the solid is " << outside("rays", "20") << " for rays, " << outside("sdf", "20")
    << " for SDF and " << outside("winding", "20") << " for the winding number; on the closed torus: "
    << outside("rays", "0") << ", " << outside("sdf", "0") << ", " << outside("winding", "0") << ".\n\n";
}

// The findings, one bullet each, from facts.json.
void findings_markdown(std::ostream& o, const json& facts) {
  o << "\n\n## Findings\n\n";
  o << "Every rate below is failures / cases with its 95% Wilson interval in brackets; every time comes from "
       "repeated runs (median, [min, max]).\n\n";
  naive_finding(o, facts);
  epsilon_finding(o, facts);
  bigtet_finding(o, facts);
  robust_finding(o, facts);
  sampling_finding(o, facts);
}

// Section 1: the failure rates.
void rates_section_markdown(std::ostream& o, const fs::path& dir, const json& rates) {
  o << "## 1. Naive floating point: failure rate per backend x family x n\n\n";
  o << "Every case is built with `naive` (no perturbation: the thesis's code), `epsilon` (absolute 1e-12), "
       "`adaptive+sos` and `exact+sos`, and checked exactly. A case fails when the build stops (`walk-cycle`, "
       "`flip-stuck`, `inconsistent-adjacency`: where the thesis's program crashed or looped) or the checker finds "
       "any defect. " << rates["cases"] << " cases per cell; families: `uniform` (general position), `clustered` "
       "(clusters down to radius 2^-40), `near_degenerate` (an exact degenerate configuration, rounded after a "
       "rotation), `ulp_jitter` (one ulp off exact), `kettner_grid` (Kettner et al.'s near-collinear grid), "
       "`torus-rays` (the thesis's ray sampler on the bumpy torus: many points on each ray, nearly collinear), "
       "`torus-winding` (winding-number sampler). For the mesh samplers and `uniform`, a larger n at the same "
       "domain is a higher density.\n\n";
  o << rates_markdown(rates);
  o << figure_markdown(dir, "fig_rates.png", "Failure rate vs n, per family and backend, with 95% Wilson intervals");
  o << figure_markdown(dir, "fig_naive_kinds.png", "Naive: what goes wrong, vs n (every family but uniform pooled; 95% Wilson intervals)");
  o << "Why: the inserter's decisions (which tet holds p, which flip) must be consistent with each other. A "
       "rounded orient3d can say p is on both sides of a facet, so the walk cycles or the 1-4 flip happens in "
       "the wrong tet (inverted, overlapping tets); a rounded insphere makes the flip loop undo its own work "
       "(flip-stuck) or leave non-Delaunay facets; a point located in an inconsistent place is skipped (missing). "
       "Near-degenerate inputs put many determinants within the rounding error, and more points give more "
       "chances.\n\n";
}

// Section 2: the epsilon "fix".
void epsilon_section_markdown(std::ostream& o, const fs::path& dir, const json& eps) {
  o << "## 2. The epsilon \"fix\"\n\n";
  o << "Families " ;
  for (const auto& f : eps["families"]) o << "`" << f.get<std::string>() << "` ";
  o << "at n = " << eps["n"] << ", " << eps["cases"] << " cases each, predicates `epsilon` without perturbation: "
       "a determinant within the band counts as 0. Absolute: `|det| <= eps`; relative: `|det| <= eps * M^k` "
       "(M the largest coordinate difference, k the degree).\n\n";
  o << eps_markdown(eps);
  o << figure_markdown(dir, "fig_epsilon.png", "Failure rate vs eps (absolute and relative), per family, with 95% Wilson intervals; dotted: naive");
}

// Section 3: the big enclosing tetrahedron.
void bigtet_section_markdown(std::ostream& o, const fs::path& dir, const json& bigtet) {
  o << "## 3. The big enclosing tetrahedron\n\n";
  o << "The thesis inserts all points into one big tetrahedron and deletes the tets touching its corners at the end. "
       "Its corners are real points, so any hull tet whose circumsphere holds a corner is never created: the "
       "result misses tets next to the hull (and holds others instead). Built here with `--boundary bigtet:FACTOR` "
       "(FACTOR = 1: the smallest regular tet holding the bounding box) and `adaptive+sos`, compared tet by tet "
       "with the infinite-vertex build of the same points. `required factor`: the smallest factor of the sweep "
       "from which every larger one gives the exact DT.\n\n";
  o << bigtet_markdown(bigtet);
  o << figure_markdown(dir, "fig_bigtet.png", "Bigtet: share of true tets missing (left) and share of inputs wrong (right, 95% Wilson intervals) vs factor");
  o << "What decides the factor is the largest circumsphere of a tet on the hull: nearly flat hull tets (random "
       "points near a facet of the box, points on parallel planes in `coplanar_slabs`) have circumspheres far "
       "larger than the input, and a corner inside one of them removes the tet. The factor any given input "
       "needs can only be found by building both, which is why dtlab uses the infinite vertex.\n\n";
}

// Section 4: the robust backends' cost.
void cost_section_markdown(std::ostream& o, const fs::path& dir, const json& cost) {
  o << "## 4. Adaptive and exact: zero defects, and their cost\n\n";
  o << "Wall time of in-process builds (median, min and max of " << cost["runs"] << " runs that interleave the "
       "backends; exact at n = 10^5: one run), the exact check of the result, and the "
       "predicate calls. `x naive` is the time relative to the naive build of the same points (naive may fail "
       "on these inputs, in which case its time is that of a wrong result).\n\n";
  o << cost_markdown(cost);
  o << figure_markdown(dir, "fig_cost.png", "Build time per backend: median, bars from the fastest to the slowest run");
}

// Section 5: the samplers.
void sampling_section_markdown(std::ostream& o, const fs::path& dir, const json& sampling) {
  o << "## 5. Ray-intersection sampling vs the winding number\n\n";
  o << "The bumpy torus (concave, with a hole; " << sampling["triangles"] << " triangles), " << sampling["count"]
    << " points per method, with every k-th triangle removed (holes, as in scanned meshes). A point is outside "
       "when the closed torus's exact winding number says so. The ray method pairs the hits along a ray by parity: "
       "a ray through a hole has an odd number of hits, the pairs shift, and whole segments outside the solid "
       "get filled.\n\n";
  o << sampling_markdown(sampling);
  o << figure_markdown(dir, "fig_sampling.png", "Share of samples outside the solid vs share of faces removed, with 95% Wilson intervals");
  o << figure_markdown(dir, "fig_sampling_slice.png", "Slab |y| < 0.05 of the torus with 5% of faces removed: outside points in red");
}

// Section 6: one overlapping configuration.
void overlap_section_markdown(std::ostream& o, const fs::path& dir, const json& overlap) {
  o << "## 6. One overlapping configuration\n\n";
  o << overlap_markdown(overlap);
  o << figure_markdown(dir, "fig_overlap.png", "A shrunk naive failure: the tets the checker names in red/orange, the rest grey");
}

std::string report_markdown(const fs::path& dir, const json& env, const json& facts, const json& rates, const json& eps,
                            const json& bigtet, const json& cost, const json& sampling, const json& overlap,
                            bool quick) {
  std::ostringstream o;
  intro_markdown(o, rates, quick);
  findings_markdown(o, facts);
  rates_section_markdown(o, dir, rates);
  epsilon_section_markdown(o, dir, eps);
  bigtet_section_markdown(o, dir, bigtet);
  cost_section_markdown(o, dir, cost);
  sampling_section_markdown(o, dir, sampling);
  overlap_section_markdown(o, dir, overlap);
  o << "## Data\n\n`data/` holds every measurement: `rates.csv`, `epsilon.csv`, `bigtet.csv`, "
       "`bigtet_required.csv`, `cost.csv`, `sampling.csv`, `slice_*.json`, `overlap_case.json` / `.xyz`, and "
       "`results.json` (all of it); `facts.json` the headline numbers. `plot_figures.py` drew the figures from "
       "them (`/usr/bin/python3 plot_figures.py .`).\n\n";
  o << environment_markdown(env);
  return o.str();
}

}  // namespace

ExperimentResult run_thesis_failures(const ThesisFailuresOptions& options) {
  const fs::path dir = options.out;
  fs::create_directories(dir / "data");
  SectionContext c{dir, options.quick, options.seed, {}};
  for (const auto& name : options.extra_predicates) {
    PredicateSpec spec;
    spec.backend = name;
    spec.perturb = false;
    c.extra_backends.push_back(spec);
  }
  const auto t0 = std::chrono::steady_clock::now();
  auto step = [&](const char* what) {
    if (options.progress)
      std::fprintf(stderr, "[%6.1f s] %s\n",
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), what);
  };
  step("failure rates per backend x family x n");
  const json rates = rates_section(c);
  step("epsilon sweep");
  const json eps = epsilon_section(c);
  step("bigtet factor sweep");
  const json bigtet = bigtet_section(c);
  step("cost of the robust backends");
  const json cost = cost_section(c);
  step("ray vs winding sampling");
  const json sampling = sampling_section(c);
  step("overlapping configuration");
  const json overlap = overlap_case_section(c);

  const json env = environment(options.command_line, options.seed);
  json facts = compute_facts(rates, eps, bigtet, cost, sampling, overlap);
  facts["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  write_text_file((dir / "data" / "facts.json").string(), facts.dump(2) + "\n");
  write_text_file((dir / "data" / "results.json").string(), json{{"experiment", "thesis-failures"}, {"quick", options.quick}, {"environment", env},
              {"rates", rates}, {"epsilon", eps}, {"bigtet", bigtet}, {"cost", cost},
              {"sampling", sampling}, {"overlap_case", overlap}}.dump(1) + "\n");
  write_text_file((dir / "environment.json").string(), env.dump(2) + "\n");
  write_text(dir / "commands.sh", "#!/bin/sh\n# the command that wrote this report\n" + options.command_line +
                                      "\n# redraw the figures from data/\n/usr/bin/python3 plot_figures.py .\n");
  if (options.figures) {
    step("figures");
    facts["figures_status"] = draw_figures(dir);
  }
  const std::string md = report_markdown(dir, env, facts, rates, eps, bigtet, cost, sampling, overlap, options.quick);
  write_text(dir / "report.md", md);
  write_text(dir / "report.html", markdown_to_html(md, "dtlab: thesis failures"));
  step("done");
  int robust = facts["robust_defects_in_cost_runs"].get<int>();
  for (const auto& [k, v] : facts["robust_failed_cases"].items()) robust += v.get<int>();
  return {robust == 0 ? 0 : 1, facts};
}

}  // namespace dtlab::experiments
