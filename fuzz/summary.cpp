#include "fuzz/summary.hpp"

#include <algorithm>
#include <cstdio>

namespace dtlab::fuzz {

Summary summarize(const std::vector<CaseRecord>& records) {
  Summary s;
  for (const auto& r : records) {
    std::string column = r.backend;
    if (r.boundary != "infinite") column += " " + r.boundary;
    SummaryCell& cell = s[{r.family, column}];
    ++cell.cases;
    cell.ok += r.run.ok();
    ++cell.outcomes[r.run.outcome];
    cell.build_seconds += r.run.build_seconds;
  }
  return s;
}

std::string summary_table(const Summary& s) {
  std::vector<std::vector<std::string>> rows = {{"family", "backend", "cases", "ok", "outcomes", "ms/case"}};
  for (const auto& [key, cell] : s) {
    std::string outcomes;
    for (const auto& [name, count] : cell.outcomes) {
      if (!outcomes.empty()) outcomes += ", ";
      outcomes += name + " " + std::to_string(count);
    }
    char ms[32];
    std::snprintf(ms, sizeof ms, "%.2f", 1e3 * cell.build_seconds / static_cast<double>(cell.cases));
    rows.push_back({key.first, key.second, std::to_string(cell.cases), std::to_string(cell.ok),
                    outcomes, ms});
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

nlohmann::json summary_json(const Summary& s) {
  nlohmann::json cells = nlohmann::json::array();
  std::size_t cases = 0, ok = 0;
  for (const auto& [key, cell] : s) {
    cells.push_back({{"family", key.first},
                     {"backend", key.second},
                     {"cases", cell.cases},
                     {"ok", cell.ok},
                     {"outcomes", cell.outcomes},
                     {"build_s", cell.build_seconds}});
    cases += cell.cases;
    ok += cell.ok;
  }
  return {{"cases", cases}, {"ok", ok}, {"failing", cases - ok}, {"cells", cells}};
}

}  // namespace dtlab::fuzz
