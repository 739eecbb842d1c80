#include "experiments/case_grid.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <string_view>

#include "fuzz/campaign.hpp"
#include "fuzz/case_seed.hpp"
#include "fuzz/families.hpp"
#include "kernel/output_file.hpp"
#include "kernel/point_io.hpp"

namespace dtlab::experiments {

namespace fs = std::filesystem;

std::vector<PointSource> fuzz_family_sources(const std::vector<std::string>& names) {
  std::vector<PointSource> out;
  for (const auto& name : names) {
    const fuzz::Family* f = fuzz::find_family(name);
    if (!f) throw std::invalid_argument("unknown family '" + name + "'");
    out.push_back({f->name, f->generate});
  }
  return out;
}

std::vector<GridCase> grid_cases(const std::vector<std::string>& peers, const CaseGrid& grid) {
  std::vector<GridCase> cases;
  for (const std::string& p : peers)
    for (const PointSource& s : grid.sources)
      for (std::size_t i = 0; i < grid.cases; ++i)
        if (!grid.only_case || *grid.only_case == i)
          cases.push_back({&p, &s, i, fuzz::case_seed(grid.seed, s.name, i)});
  return cases;
}

std::vector<Point3> grid_points(const GridCase& c, const CaseGrid& grid) {
  return c.source->generate(fuzz::case_points(c.seed, grid.min_points, grid.max_points), c.seed);
}

std::string grid_case_command(const std::string& target, const CaseGrid& grid, const std::string& source,
                              std::size_t index) {
  return "dtlab fuzz --target " + target + " --family " + source + " --case " + std::to_string(index) + " --seed " +
         std::to_string(grid.seed) + " --min-points " + std::to_string(grid.min_points) + " --points " +
         std::to_string(grid.max_points) + " --out DIR";
}

double shrink_try_limit(double original_seconds, double timeout_s) {
  return std::clamp(10 * original_seconds, std::min(2.0, timeout_s), timeout_s);
}

std::string corpus_prefix(const std::string& peer, const std::string& source) {
  static constexpr char hex[] = "0123456789ABCDEF";
  std::string prefix;
  for (const char ch : peer) {
    const auto b = static_cast<unsigned char>(ch);
    if ((ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '.' || ch == '-' ||
        ch == '+') {
      prefix += ch;
    } else if (ch == ':') {
      prefix += '_';
    } else {
      prefix += '~';
      prefix += hex[b >> 4];
      prefix += hex[b & 15];
    }
  }
  return prefix + "-" + source;
}

std::string corpus_stem(const std::string& peer, const std::string& source, std::size_t n, std::size_t index) {
  return corpus_prefix(peer, source) + "-n" + std::to_string(n) + "-" + std::to_string(index);
}

namespace {

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
}

}  // namespace

std::optional<CorpusName> parse_corpus_name(const std::string& file_name) {
  const fs::path p(file_name);
  if (p.extension() != ".node" && p.extension() != ".json") return std::nullopt;
  const std::string stem = p.stem().string();
  const std::size_t dash = stem.rfind('-');
  if (dash == std::string::npos || !all_digits(std::string_view(stem).substr(dash + 1))) return std::nullopt;
  const std::size_t n_at = stem.rfind("-n", dash);
  if (n_at == std::string::npos || n_at == 0 || !all_digits(std::string_view(stem).substr(n_at + 2, dash - n_at - 2)))
    return std::nullopt;
  CorpusName name{stem.substr(0, n_at), 0};
  const auto [end, ec] = std::from_chars(stem.data() + dash + 1, stem.data() + stem.size(), name.index);
  if (ec != std::errc()) return std::nullopt;  // beyond size_t: no case of ours
  return name;
}

std::vector<std::string> remove_corpus_names(const std::string& out_dir,
                                             const std::function<bool(const CorpusName&, const std::string&)>& ours) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(fs::path(out_dir) / "corpus", ec)) {
    const std::string file_name = e.path().filename().string();
    if (const auto name = parse_corpus_name(file_name); name && ours(*name, file_name))
      files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return remove_output_set(files);
}

namespace {

// The prefixes of the names before the one-to-one escape (2026-12-07): the peer with ':'
// as '_', and in the Voronoi campaign '+' as 'p' too. Not one to one (dtlab:exact and
// dtlab_exact shared a name), so such a file is a case's only when its sidecar says so.
std::vector<std::string> legacy_corpus_prefixes(const std::string& peer, const std::string& source) {
  std::string colon = peer + "-" + source;
  std::replace(colon.begin(), colon.end(), ':', '_');
  std::string plus = colon;
  std::replace(plus.begin(), plus.end(), '+', 'p');
  std::vector<std::string> out;
  for (std::string* p : {&colon, &plus})
    if (*p != corpus_prefix(peer, source) && std::find(out.begin(), out.end(), *p) == out.end()) out.push_back(*p);
  return out;
}

// The "peer" of the sidecar of corpus name `n` (<dir>/<prefix>-n*-<index>.json, any n),
// "" when there is none or it cannot be read.
std::string sidecar_peer(const fs::path& dir, const std::string& file_name) {
  fs::path side = dir / file_name;
  side.replace_extension(".json");
  std::ifstream in(side, std::ios::binary);
  if (!in) return "";
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    return j.is_object() && j.contains("peer") && j["peer"].is_string() ? j["peer"].get<std::string>() : "";
  } catch (const nlohmann::json::exception&) {
    return "";
  }
}

}  // namespace

void remove_grid_corpus(const std::vector<std::string>& peers, const CaseGrid& grid) {
  std::set<std::pair<std::string, std::size_t>> cases;
  std::map<std::pair<std::string, std::size_t>, std::set<std::string>> legacy;  // (old prefix, case) -> peers
  for (const GridCase& c : grid_cases(peers, grid)) {
    cases.insert({corpus_prefix(*c.peer, c.source->name), c.index});
    for (const std::string& old : legacy_corpus_prefixes(*c.peer, c.source->name))
      legacy[{old, c.index}].insert(*c.peer);
  }
  const fs::path dir = fs::path(grid.out_dir) / "corpus";
  remove_corpus_names(grid.out_dir, [&](const CorpusName& n, const std::string& file_name) {
    if (cases.count({n.prefix, n.index})) return true;
    const auto old = legacy.find({n.prefix, n.index});
    return old != legacy.end() && old->second.count(sidecar_peer(dir, file_name)) > 0;
  });
}

std::string save_corpus_points(const std::string& out_dir, const std::string& stem, const std::vector<Point3>& points) {
  const fs::path dir = fs::path(out_dir) / "corpus";
  fs::create_directories(dir);
  write_node((dir / (stem + ".node")).string(), points);
  return "corpus/" + stem + ".node";
}

void save_corpus_sidecar(const std::string& out_dir, const std::string& stem, const nlohmann::json& sidecar) {
  write_text_file((fs::path(out_dir) / "corpus" / (stem + ".json")).string(), sidecar.dump(2) + "\n");
}

}  // namespace dtlab::experiments
