// _core.fuzz_families, _core.fuzz_generate, _core.fuzz_case_seed, _core.fuzz_case_points:
// the fuzz module's point-set registry, bit for bit what `dtlab fuzz` generates.
// _core.fuzz_peer_campaign: `dtlab fuzz --target PEER` (experiments/peer_campaign.hpp)
// on a peer name or a Python callable, with progress= per family; _core.wilson_interval: its rates' intervals.
#include <functional>
#include <map>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>

#include <pybind11/stl.h>
#include "experiments/peer_campaign.hpp"
#include "fuzz/campaign.hpp"
#include "fuzz/case_seed.hpp"
#include "fuzz/families.hpp"
#include "fuzz/rate_interval.hpp"
#include "oracle/peers/temp_dir.hpp"
#include "python/src/bindings.hpp"
#include "python/src/function_peers.hpp"
#include "python/src/interrupt_check.hpp"
#include "python/src/numpy_io.hpp"
#include "python/src/progress_callback.hpp"

namespace py = pybind11;

namespace dtlab::python {
namespace {

py::list families() {
  py::list l;
  for (const fuzz::Family& f : fuzz::families()) l.append(py::make_tuple(f.name, f.description));
  return l;
}

py::array_t<double> generate(const std::string& family, std::size_t n, std::uint64_t seed) {
  const fuzz::Family* f = fuzz::find_family(family);
  if (!f) throw py::value_error("family: unknown family '" + family + "' (see dtlab fuzz --list)");
  std::vector<Point3> points;
  {
    py::gil_scoped_release nogil;
    points = f->generate(n, seed);
  }
  return points_to_numpy(std::move(points));
}

py::dict case_dict(experiments::PeerCase& c, bool keep_files) {
  py::dict d;
  d["family"] = c.source;
  d["index"] = c.index;
  d["case_seed"] = c.seed;
  d["n"] = c.n;
  d["lower_dimensional"] = c.lower_dimensional;
  d["verdict"] = verdict_name(c.run.verdict);
  d["message"] = c.run.message;
  d["seconds"] = c.run.wall_seconds;
  d["failed"] = c.failed();
  const bool shrunk = !c.shrunk_input.empty();
  d["shrunk"] = shrunk ? py::object(points_to_numpy(std::move(c.shrunk_input))) : py::none();
  d["shrunk_verdict"] = shrunk ? py::object(py::str(verdict_name(c.shrunk_verdict))) : py::none();
  d["minimal"] = shrunk && c.shrunk_minimal;
  d["shrink_stop"] = c.shrink_stop;
  d["shrink_runs"] = c.shrink_runs;
  d["corpus_file"] = keep_files ? c.corpus_file : "";
  return d;
}

// progress(done, total, FAMILY) after each case: the family's cases done, of `cases`
// (the campaign runs one case at a time, on the calling thread).
void report_cases(experiments::PeerCampaignOptions& o, std::function<void(const ProgressEvent&)> emit) {
  o.on_case = [emit = std::move(emit), total = o.cases,
               done = std::map<std::string, std::size_t>()](const experiments::PeerCase& c) mutable {
    emit(ProgressEvent{c.source, ++done[c.source], total});
  };
}

// The CLI's run_target (cli/cmd_fuzz.cpp) without its table: the same cases, seeds,
// verdicts and shrinking. Without an out folder the corpus goes to a temporary one.
py::list peer_campaign(const std::string& target, const py::dict& functions, const std::vector<std::string>& families,
                       std::size_t cases, std::size_t min_points, std::size_t max_points, std::uint64_t seed,
                       const std::string& out_dir, bool shrink, std::size_t shrink_budget, double timeout,
                       double memory_mb, const py::object& progress) {
  if (!(timeout >= 0.001 && timeout <= 1e6)) throw py::value_error("timeout: must be a number in [0.001, 1e6]");
  if (!(memory_mb >= 0 && memory_mb <= 1e9)) throw py::value_error("memory_mb: must be a number in [0, 1e9]");
  // The CLI's ranges (cli/cmd_fuzz.cpp): 10^12 points ended in std::bad_alloc.
  for (auto [name, v] : {std::pair{"points", max_points}, std::pair{"min_points", min_points}})
    if (v < 1 || v > 10000000) throw py::value_error(std::string(name) + ": " + std::to_string(v) + " not in [1, 1e7]");
  if (cases > 1000000000000ull) throw py::value_error("cases: " + std::to_string(cases) + " not in [0, 1e12]");
  if (min_points > max_points)
    throw py::value_error("min_points " + std::to_string(min_points) + " is above points " +
                          std::to_string(max_points));
  const FunctionPeers function_peers(functions);
  if (!is_peer_name(target)) throw py::value_error("unknown peer '" + target + "' (see dtlab oracle --help)");
  experiments::PeerCampaignOptions o;
  o.peer = target;
  try {
    o.sources = experiments::fuzz_family_sources(families);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("families: ") + e.what() + " (see dtlab fuzz --list)");
  }
  o.cases = cases;
  o.min_points = min_points;
  o.max_points = max_points;
  o.seed = seed;
  o.shrink = shrink;
  o.shrink_budget = shrink_budget;
  o.peer_options.timeout_s = timeout;
  o.peer_options.memory_bytes = static_cast<std::uint64_t>(memory_mb * 1e6);
  std::optional<TempDir> scratch;
  if (out_dir.empty()) scratch.emplace("dtlab-campaign");
  o.out_dir = out_dir.empty() ? scratch->path().string() : out_dir;
  if (!progress.is_none()) report_cases(o, pending_callback(progress));
  std::vector<experiments::PeerCase> results;
  bool interrupted = false;
  {
    const InterruptCheck check;
    py::gil_scoped_release nogil;
    try {
      results = experiments::run_peer_campaign(o);
    } catch (const ChildInterrupted&) {
      interrupted = true;  // the KeyboardInterrupt (or the runner's or progress's error) is pending, raised below
    } catch (const std::bad_alloc&) {
      throw;  // MemoryError, not bad input (as the CLI's exit 1)
    } catch (const std::exception& e) {
      py::gil_scoped_acquire gil;
      throw py::value_error(e.what());
    }
  }
  if (interrupted) throw py::error_already_set();
  py::list out;
  for (auto& c : results) out.append(case_dict(c, !out_dir.empty()));
  return out;
}

}  // namespace

void bind_fuzz(py::module_& m) {
  m.def("fuzz_families", &families, "[(name, description)] of every point-set family.");
  m.def("fuzz_generate", &generate, py::arg("family"), py::arg("n"), py::arg("seed"),
        "n points of a family from a seed (see dtlab.fuzz.generate).");
  m.def("fuzz_case_seed", [](std::uint64_t seed, const std::string& family, std::uint64_t index) {
    return fuzz::case_seed(seed, family, index);
  }, py::arg("seed"), py::arg("family"), py::arg("index"), "The seed of case `index` of `family` in a campaign.");
  m.def("fuzz_case_points", &fuzz::case_points, py::arg("case_seed"), py::arg("min_points"), py::arg("max_points"),
        "The number of points of a campaign case, drawn from its seed.");
  m.def("fuzz_peer_campaign", &peer_campaign, py::arg("target"), py::arg("functions"), py::arg("families"),
        py::arg("cases"), py::arg("min_points"), py::arg("max_points"), py::arg("seed"), py::arg("out_dir"),
        py::arg("shrink"), py::arg("shrink_budget"), py::arg("timeout"), py::arg("memory_mb"),
        py::arg("progress") = py::none(),
        "`dtlab fuzz --target PEER` on a peer name or a callable (see dtlab.fuzz.campaign).");
  m.def(
      "wilson_interval",
      [](std::size_t failures, std::size_t cases) {
        const fuzz::RateInterval r = fuzz::wilson_interval(failures, cases);
        return py::make_tuple(r.rate, r.low, r.high);
      },
      py::arg("failures"), py::arg("cases"), "(rate, low, high): the 95% Wilson score interval of a failure rate.");
}

}  // namespace dtlab::python
