#include "fuzz/record_json.hpp"

namespace dtlab::fuzz {

nlohmann::json record_to_json(const CaseRecord& r) {
  nlohmann::json j = {
      {"id", r.id},
      {"family", r.family},
      {"case", r.index},
      {"campaign_seed", r.campaign_seed},
      {"case_seed", r.case_seed},
      {"points", r.points},
      {"backend", r.backend},
      {"predicates", r.predicates},
      {"perturb", r.perturb ? "sos" : "none"},
      {"boundary", r.boundary},
      {"threads", r.threads},
      {"outcome", r.run.outcome},
      {"ok", r.run.ok()},
      {"defects", r.run.defects},
      {"tets", r.run.tets},
      {"duplicates", r.run.duplicates},
      {"build_s", r.run.build_seconds},
      {"check_s", r.run.check_seconds},
      {"dtlab_version", r.version},
      {"dtlab_commit", r.commit},
  };
  if (!r.run.detail.empty()) j["detail"] = r.run.detail;
  if (r.shrunk_points) {
    j["shrunk_points"] = r.shrunk_points;
    j["corpus"] = r.corpus_file;
  }
  return j;
}

CaseRecord record_from_json(const nlohmann::json& j) {
  CaseRecord r;
  r.id = j.at("id").get<std::string>();
  r.family = j.at("family").get<std::string>();
  r.index = j.at("case").get<std::size_t>();
  r.campaign_seed = j.at("campaign_seed").get<std::uint64_t>();
  r.case_seed = j.at("case_seed").get<std::uint64_t>();
  r.points = j.at("points").get<std::size_t>();
  r.backend = j.at("backend").get<std::string>();
  r.predicates = j.at("predicates").get<std::string>();
  r.perturb = j.at("perturb").get<std::string>() == "sos";
  r.boundary = j.at("boundary").get<std::string>();
  r.threads = j.value("threads", 0u);  // absent in lines written before the thread count was kept
  r.run.outcome = j.at("outcome").get<std::string>();
  r.run.defects = j.value("defects", std::map<std::string, std::uint64_t>{});
  r.run.detail = j.value("detail", std::string{});
  r.run.tets = j.value("tets", std::uint64_t{0});
  r.run.duplicates = j.value("duplicates", std::uint64_t{0});
  r.run.build_seconds = j.value("build_s", 0.0);
  r.run.check_seconds = j.value("check_s", 0.0);
  r.shrunk_points = j.value("shrunk_points", std::size_t{0});
  r.corpus_file = j.value("corpus", std::string{});
  r.version = j.value("dtlab_version", std::string{});  // absent in lines written before 0.1.0's commit field
  r.commit = j.value("dtlab_commit", std::string{});
  return r;
}

}  // namespace dtlab::fuzz
