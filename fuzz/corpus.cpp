#include "fuzz/corpus.hpp"

#include <cstdint>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "fuzz/campaign_settings.hpp"
#include "kernel/input_error.hpp"
#include "kernel/output_file.hpp"
#include "kernel/point_io.hpp"
#include "oracle/peers/json_fields.hpp"
#include "predicates/backend_choice.hpp"

namespace dtlab::fuzz {

namespace fs = std::filesystem;

namespace {

std::string file_stem(const CaseRecord& r) {
  std::string name = r.id + "-" + r.backend;
  if (r.boundary != "infinite") name += "-" + r.boundary;
  std::replace(name.begin(), name.end(), ':', '_');
  return name;
}

// The 1-based line of byte `offset` in `text`.
std::size_t line_at(const std::string& text, std::size_t offset) {
  offset = std::min(offset, text.size());
  return 1 +
         static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

// The most threads a sidecar may name: --threads's bound (a recorded count is resolved, never 0).
constexpr std::int64_t kMaxSidecarThreads = 1024;

// The settings a corpus file was recorded with, from its .json sidecar when there is one:
// backend, boundary, case seed, insertion order and the build's threads (build.threads as
// recorded; the caller applies use_build_threads). Fields a sidecar does not have (older
// ones lack "order" and "threads") keep their defaults: brio, serial. A sidecar that is no
// JSON, holds a field of the wrong type or names an unknown backend, boundary or order or a
// thread count out of range is refused with its file and line (the line of the field when
// it is found). "against" (the oracles the case was compared with) must be a list of names;
// older sidecars lack it: none.
struct RecordedOracles {
  std::vector<std::string> names;
  std::string sidecar;   // the file, "" without one
  std::size_t line = 0;  // of "against" in it
};

void read_sidecar(const fs::path& file, PredicateSpec& spec, BuildOptions& build, std::string& outcome,
                  RecordedOracles& against) {
  fs::path sidecar = file;
  sidecar.replace_extension(".json");
  std::string boundary = "infinite";
  std::string order = "brio";
  nlohmann::json threads = 1, eps = nullptr, eps_mode = nullptr, oracles = nlohmann::json::array();
  if (fs::is_regular_file(sidecar)) {
    std::ifstream in(sidecar, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw InputError(sidecar.string(), 0, "read error");
    const auto field_line = [&](const char* key) {
      const std::size_t at = text.find('"' + std::string(key) + '"');
      return at == std::string::npos ? std::size_t(0) : line_at(text, at);
    };
    nlohmann::json j;
    try {
      j = parse_unique_fields(text);
    } catch (const nlohmann::json::parse_error& e) {
      throw InputError(sidecar.string(), line_at(text, e.byte == 0 ? 0 : e.byte - 1), e.what());
    } catch (const DuplicateField& e) {
      throw InputError(sidecar.string(), field_line(e.field.c_str()), e.what());
    }
    if (!j.is_object()) throw InputError(sidecar.string(), 1, "expected a JSON object");
    const char* key = "";
    try {
      key = "predicates", spec.backend = j.value(key, spec.backend);
      key = "perturb", spec.perturb = j.value(key, std::string("sos")) == "sos";
      key = "boundary", boundary = j.value(key, boundary);
      key = "outcome", outcome = j.value(key, std::string{});
      key = "case_seed", build.seed = j.value(key, build.seed);
      key = "order", order = j.value(key, order);
      key = "threads", threads = j.value(key, threads);
      key = "eps", eps = j.value(key, eps);
      key = "eps_mode", eps_mode = j.value(key, eps_mode);
      key = "against", oracles = j.value(key, oracles);
    } catch (const nlohmann::json::exception& e) {
      throw InputError(sidecar.string(), field_line(key), std::string("'") + key + "': " + e.what());
    }
    if (!parse_backend(spec.backend))
      throw InputError(sidecar.string(), field_line("predicates"),
                       "unknown predicates '" + spec.backend + "' (expected naive, epsilon, adaptive or exact)");
    if (!parse_boundary(boundary, build))
      throw InputError(sidecar.string(), field_line("boundary"), "bad boundary '" + boundary + "'");
    if (order != "brio" && order != "input")
      throw InputError(sidecar.string(), field_line("order"), "bad order '" + order + "' (expected brio or input)");
    if (!threads.is_number_integer() || threads.get<std::int64_t>() < 1 ||
        threads.get<std::int64_t>() > kMaxSidecarThreads)
      throw InputError(sidecar.string(), field_line("threads"),
                       "bad threads " + threads.dump() + " (expected 1 to " + std::to_string(kMaxSidecarThreads) +
                           ": the build's thread count, 1 serial)");
    if (!eps.is_null() && !(eps.is_number() && eps.get<double>() > 0 && std::isfinite(eps.get<double>())))
      throw InputError(sidecar.string(), field_line("eps"), "bad eps " + eps.dump() + " (expected a positive number)");
    if (!eps_mode.is_null() && eps_mode != "absolute" && eps_mode != "relative")
      throw InputError(sidecar.string(), field_line("eps_mode"),
                       "bad eps_mode " + eps_mode.dump() + " (expected absolute or relative)");
    const auto is_name = [](const nlohmann::json& n) { return n.is_string() && !n.get<std::string>().empty(); };
    if (!oracles.is_array() || !std::all_of(oracles.begin(), oracles.end(), is_name))
      throw InputError(sidecar.string(), field_line("against"),
                       "bad against " + oracles.dump() + " (expected a list of oracle names)");
    against = {oracles.get<std::vector<std::string>>(), sidecar.string(), field_line("against")};
    if (!eps.is_null()) spec.eps = eps.get<double>();  // older sidecars: the default band
    if (!eps_mode.is_null()) spec.relative_eps = eps_mode == "relative";
    build.order = order == "input" ? InsertionOrder::input : InsertionOrder::brio;
    build.threads = threads.get<unsigned>();
  } else {
    parse_boundary(boundary, build);
  }
}

}  // namespace

bool parse_boundary(const std::string& text, BuildOptions& options) {
  if (text == "infinite") {
    options.boundary = Boundary::infinite;
    return true;
  }
  if (text.rfind("bigtet", 0) != 0) return false;
  options.boundary = Boundary::bigtet;
  if (text == "bigtet") return true;
  if (text[6] != ':') return false;
  try {
    std::size_t used = 0;
    const double f = std::stod(text.substr(7), &used);
    // Finite, and at least 1 (the smallest tet holding the bounding box).
    if (used != text.size() - 7 || !(std::isfinite(f) && f >= 1)) return false;
    options.bigtet_factor = f;
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

std::vector<std::string> corpus_entry_files(const std::string& out_dir, const CaseRecord& record) {
  const fs::path stem = fs::path(out_dir) / "corpus" / file_stem(record);
  return {stem.string() + ".node", stem.string() + ".json"};
}

std::string write_corpus_entry(const std::string& out_dir, const CaseRecord& record,
                               const std::vector<Point3>& points, const CorpusEntryInfo& info) {
  const fs::path dir = fs::path(out_dir) / "corpus";
  fs::create_directories(dir);
  const std::string stem = file_stem(record);
  write_node((dir / (stem + ".node")).string(), points);
  const std::string relative = "corpus/" + stem + ".node";
  nlohmann::json j = {
      {"id", record.id},
      {"family", record.family},
      {"case", record.index},
      {"campaign_seed", record.campaign_seed},
      {"case_seed", record.case_seed},
      {"points_original", record.points},
      {"points", points.size()},
      {"predicates", record.predicates},
      {"perturb", record.perturb ? "sos" : "none"},
      {"boundary", record.boundary},
      {"order", info.order},
      {"eps", record.predicates == "epsilon" ? nlohmann::json(info.eps) : nlohmann::json(nullptr)},
      {"eps_mode", record.predicates == "epsilon" ? nlohmann::json(info.relative_eps ? "relative" : "absolute")
                                                  : nlohmann::json(nullptr)},
      {"threads", record.threads},
      {"against", info.against},
      {"outcome", record.run.outcome},
      {"detail", record.run.detail},
      {"shrink_tests", info.shrink_tests},
      {"minimal", info.minimal},
      {"reproduce", "dtlab fuzz --replay " + (fs::path(out_dir) / relative).string()},
      {"reproduce_original", info.original_command},
  };
  write_text_file((dir / (stem + ".json")).string(), j.dump(2) + "\n");
  return relative;
}

std::vector<ReplayResult> replay_corpus(const std::string& path, const ReplayOptions& options) {
  std::vector<fs::path> files;
  const fs::path p(path);
  if (fs::is_regular_file(p)) {
    files.push_back(p);
  } else if (fs::is_directory(p)) {
    const fs::path dir = fs::is_directory(p / "corpus") ? p / "corpus" : p;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file() && e.path().extension() == ".node") files.push_back(e.path());
    std::sort(files.begin(), files.end());
  } else {
    throw InputError(path, 0, "no such file or folder");
  }

  std::vector<ReplayResult> results;
  for (const auto& file : files) {
    const std::vector<Point3> points = read_points(file.string()).points;
    PredicateSpec recorded_spec;
    BuildOptions build;
    std::string recorded_outcome;
    RecordedOracles recorded_against;
    read_sidecar(file, recorded_spec, build, recorded_outcome, recorded_against);
    if (options.boundary) {
      build.boundary = options.boundary->boundary;
      build.bigtet_factor = options.boundary->bigtet_factor;
    }
    if (options.order) build.order = *options.order;
    // The campaign's threaded build (parallel_grain 1 above one thread), or the serial one.
    use_build_threads(build, options.threads.value_or(build.threads));
    const std::vector<PredicateSpec> specs =
        options.backends.empty() ? std::vector<PredicateSpec>{recorded_spec} : options.backends;
    const std::vector<std::string> against = options.against.value_or(recorded_against.names);
    if (!against.empty() && !options.oracles)
      throw std::invalid_argument(file.string() + " was compared with oracles and this replay has none to run");
    // The hooks of the recorded names; a name no oracle has is the sidecar's defect.
    const auto hooks = [&](const PredicateSpec& spec) {
      try {
        return options.oracles(against, spec, build);
      } catch (const std::invalid_argument& e) {
        if (options.against) throw;
        throw InputError(recorded_against.sidecar, static_cast<long>(recorded_against.line), e.what());
      }
    };
    for (const auto& spec : specs) {
      ReplayResult r;
      r.file = file.string();
      r.recorded_outcome = recorded_outcome;
      r.backend = backend_label(spec);
      r.boundary = boundary_label(build);
      r.threads = build_thread_count(build);
      r.order = order_label(build);
      r.against = against;
      r.run = against.empty() ? run_case(points, spec, build) : run_case(points, spec, build, hooks(spec));
      results.push_back(std::move(r));
    }
  }
  return results;
}

}  // namespace dtlab::fuzz
