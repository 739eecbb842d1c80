#include "fuzz/summary.hpp"

#include <algorithm>
#include <cstdio>

namespace dtlab::fuzz {

namespace {

std::string join_counts(const std::map<std::string, std::size_t>& counts) {
  std::string out;
  for (const auto& [name, count] : counts) {
    if (!out.empty()) out += ", ";
    out += name + " " + std::to_string(count);
  }
  return out;
}

bool ok_outcome(const std::string& outcome) { return outcome == "valid" || outcome == "lower-dimensional"; }

}  // namespace

std::map<std::string, std::size_t> SummaryCell::failure_kinds() const {
  std::map<std::string, std::size_t> kinds;
  for (const auto& [name, count] : outcomes)
    if (!ok_outcome(name)) kinds[name] = count;
  return kinds;
}

std::size_t Summary::cases() const {
  std::size_t n = 0;
  for (const auto& [key, cell] : cells) n += cell.cases;
  return n;
}

std::size_t Summary::failures() const {
  std::size_t n = 0;
  for (const auto& [key, cell] : cells) n += cell.failures();
  return n;
}

Summary summarize(const std::vector<CaseRecord>& records) {
  Summary s;
  for (const auto& r : records) {
    std::string column = r.backend;
    if (r.boundary != "infinite") column += " " + r.boundary;
    SummaryCell& cell = s.cells[{r.family, column}];
    ++cell.cases;
    cell.ok += r.run.ok();
    ++cell.outcomes[r.run.outcome];
    cell.build_seconds += r.run.build_seconds;
    s.builds.insert((r.version.empty() ? "unknown" : r.version) + " " + (r.commit.empty() ? "unknown" : r.commit));
  }
  return s;
}

std::string summary_table(const Summary& s, bool with_timing) {
  std::vector<std::vector<std::string>> rows = {
      {"family", "backend", "cases", "failures", "failure rate [95% CI]", "kinds of failure", "outcomes"}};
  if (with_timing) rows[0].push_back("ms/case");
  for (const auto& [key, cell] : s.cells) {
    const auto kinds = cell.failure_kinds();
    rows.push_back({key.first, key.second, std::to_string(cell.cases), std::to_string(cell.failures()),
                    rate_text(cell.failure_rate()), kinds.empty() ? "-" : join_counts(kinds),
                    join_counts(cell.outcomes)});
    if (with_timing) {
      char ms[32];
      std::snprintf(ms, sizeof ms, "%.2f", 1e3 * cell.build_seconds / static_cast<double>(cell.cases));
      rows.back().push_back(ms);
    }
  }
  std::vector<std::size_t> width(rows[0].size(), 0);
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  std::string out;
  const auto emit = [&](const std::vector<std::string>& row) {
    out += "|";
    for (std::size_t c = 0; c < row.size(); ++c)
      out += " " + row[c] + std::string(width[c] - row[c].size(), ' ') + " |";
    out += "\n";
  };
  emit(rows[0]);
  out += "|";
  for (std::size_t w : width) out += std::string(w + 2, '-') + "|";
  out += "\n";
  for (std::size_t i = 1; i < rows.size(); ++i) emit(rows[i]);
  return out;
}

std::string summary_markdown(const Summary& s) {
  std::string builds;
  for (const auto& b : s.builds) {
    if (!builds.empty()) builds += ", ";
    builds += '`';
    builds += b;
    builds += '`';
  }
  std::string out = "# Fuzz campaign summary\n\n";
  out += std::to_string(s.cases()) + " results (case x backend), " + std::to_string(s.failures()) +
         " failures. dtlab build(s) (version commit): " + (builds.empty() ? "none" : builds) + ".\n\n";
  out += "A failure is any outcome other than `valid` or `lower-dimensional` (a flat input proven flat). "
         "Rates are failures / cases with the 95% Wilson score interval in brackets, in percent. "
         "The machine, command line and seeds are in `environment*.json`; every result is a line of "
         "`results*.jsonl`.\n\n";
  out += summary_table(s, false);
  return out;
}

nlohmann::json summary_json(const Summary& s, bool with_timing) {
  nlohmann::json cells = nlohmann::json::array();
  for (const auto& [key, cell] : s.cells) {
    const RateInterval r = cell.failure_rate();
    nlohmann::json c = {{"family", key.first},
                        {"backend", key.second},
                        {"cases", cell.cases},
                        {"ok", cell.ok},
                        {"failures", cell.failures()},
                        {"rate", r.rate},
                        {"ci95", {r.low, r.high}},
                        {"failure_kinds", cell.failure_kinds()},
                        {"outcomes", cell.outcomes}};
    if (with_timing) c["build_s"] = cell.build_seconds;
    cells.push_back(std::move(c));
  }
  const std::size_t cases = s.cases(), failing = s.failures();
  return {{"cases", cases}, {"ok", cases - failing}, {"failing", failing},
          {"interval", "Wilson score, 95%"}, {"builds", s.builds}, {"cells", cells}};
}

}  // namespace dtlab::fuzz
