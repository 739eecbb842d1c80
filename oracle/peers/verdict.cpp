#include "oracle/peers/verdict.hpp"

namespace dtlab {

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::delaunay: return "delaunay";
    case Verdict::triangulation: return "triangulation";
    case Verdict::flat_tets: return "flat-tets";
    case Verdict::invalid: return "invalid";
    case Verdict::unproven: return "unproven";
    case Verdict::missing_points: return "missing-points";
    case Verdict::extra_points: return "extra-points";
    case Verdict::crashed: return "crashed";
    case Verdict::hung: return "hung";
    case Verdict::out_of_memory: return "out-of-memory";
    case Verdict::refused: return "refused";
    case Verdict::not_installed: return "not-installed";
  }
  return "?";
}

bool no_answer(Verdict v) {
  return v == Verdict::crashed || v == Verdict::hung || v == Verdict::out_of_memory || v == Verdict::refused ||
         v == Verdict::not_installed;
}

Verdict verdict_of(const CheckReport& report) {
  const auto count = [&](DefectKind k) { return report.counts[static_cast<int>(k)]; };
  std::uint64_t structural = 0;
  for (int k = 0; k < kDefectKinds; ++k) {
    const auto kind = static_cast<DefectKind>(k);
    if (kind != DefectKind::non_delaunay && kind != DefectKind::flat && kind != DefectKind::missing_point &&
        kind != DefectKind::unproven)
      structural += report.counts[k];
  }
  if (structural) return Verdict::invalid;
  if (count(DefectKind::unproven)) return Verdict::unproven;
  if (count(DefectKind::missing_point)) return Verdict::missing_points;
  if (count(DefectKind::flat)) return Verdict::flat_tets;
  if (count(DefectKind::non_delaunay)) return Verdict::triangulation;
  return Verdict::delaunay;
}

std::string defect_counts_text(const CheckReport& report) {
  std::string s;
  for (int k = 0; k < kDefectKinds; ++k) {
    if (!report.counts[k]) continue;
    if (!s.empty()) s += ", ";
    s += std::string(defect_name(static_cast<DefectKind>(k))) + " " + std::to_string(report.counts[k]);
  }
  return s;
}

}  // namespace dtlab
