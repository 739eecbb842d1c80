#include "oracle/peers/peers.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "kernel/input_error.hpp"
#include "kernel/output_file.hpp"
#include "kernel/parallel_for.hpp"
#include "kernel/point_io.hpp"
#include "kernel/tet_io.hpp"
#include "oracle/peers/child_process.hpp"
#include "oracle/peers/peer_adapter.hpp"
#include "oracle/peers/peer_child.hpp"
#include "oracle/peers/peer_command.hpp"
#include "oracle/peers/peer_exchange.hpp"
#include "oracle/peers/peer_function.hpp"
#include "oracle/peers/served_child.hpp"
#include "oracle/peers/temp_dir.hpp"
#include "oracle/peers/tetgen_oracle.hpp"

#ifndef DTLAB_PEER_BINARY
#define DTLAB_PEER_BINARY "dtlab_peer"
#endif
#ifndef DTLAB_PEER_GMSH_BINARY
#define DTLAB_PEER_GMSH_BINARY "dtlab_peer_gmsh"
#endif

namespace dtlab {
namespace {

enum class Runner { helper, tetgen, python };

struct PeerSpec {
  const char* name;
  Runner runner;
  PeerOrientation orientation;
  bool slow_start = false;  // its helper has a --serve mode (PeerOptions::servers)
  bool threaded = false;    // its helper takes a THREADS argument (PeerOptions::threads)
};

const PeerSpec kPeers[] = {
    {"cgal", Runner::helper, PeerOrientation::dtlab},
    {"cgal-inexact", Runner::helper, PeerOrientation::swapped},
    {"cgal-parallel", Runner::helper, PeerOrientation::swapped, false, true},
    {"tetgen", Runner::tetgen, PeerOrientation::dtlab},
    {"tetgen-flip", Runner::tetgen, PeerOrientation::dtlab},
    {"qhull", Runner::helper, PeerOrientation::by_sign},
    {"qhull-qj", Runner::helper, PeerOrientation::by_sign},
    {"scipy", Runner::python, PeerOrientation::by_sign, true},
    {"gmsh", Runner::helper, PeerOrientation::by_sign, true},
    {"gmsh-hxt", Runner::helper, PeerOrientation::by_sign, true, true},
    {"dtlab:naive", Runner::helper, PeerOrientation::dtlab},
    {"dtlab:epsilon", Runner::helper, PeerOrientation::dtlab},
    {"dtlab:adaptive", Runner::helper, PeerOrientation::dtlab},
    {"dtlab:exact", Runner::helper, PeerOrientation::dtlab},
};

std::optional<PeerSpec> find_peer(const std::string& name) {
  for (const PeerSpec& p : kPeers)
    if (name == p.name) return p;
  // dtlab:plugin:PATH: dtlab's inserter with a predicate plug-in, in the helper.
  if (name.rfind("dtlab:plugin:", 0) == 0 && name.size() > 13 && name.find("+none") == std::string::npos)
    return PeerSpec{"dtlab:plugin", Runner::helper, PeerOrientation::dtlab};
  // dtlab:B+none: the same backend without symbolic perturbation.
  const std::string suffix = "+none";
  if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
    auto base = find_peer(name.substr(0, name.size() - suffix.size()));
    if (base && std::string(base->name).rfind("dtlab:", 0) == 0)
      return PeerSpec{"", Runner::helper, PeerOrientation::dtlab};
  }
  return std::nullopt;
}

// scipy.spatial.Delaunay with its defaults; exit 4: not installed, 3: refused.
// `--serve`: requests "IN<TAB>OUT" on stdin, replies "CODE MESSAGE" on fd 3
// (oracle/peers/peer_serve.hpp's protocol).
const char* kScipyScript = R"PY(
import os, sys, struct, time
try:
    import numpy as np
    import scipy
    from scipy.spatial import Delaunay
except Exception as e:
    print("not installed: %s" % e, file=sys.stderr); sys.exit(4)

def run(inp, out):
    data = open(inp, "rb").read()
    if data[:4] != b"DTLP":
        return 2, "not a dtlab peer file"
    n = struct.unpack("<Q", data[4:12])[0]
    pts = np.frombuffer(data, dtype="<f8", count=3 * n, offset=12).reshape(n, 3)
    t = time.perf_counter()
    try:
        d = Delaunay(pts)
    except Exception as e:
        lines = [l for l in str(e).splitlines() if l.strip()]
        qh = [l for l in lines if l.startswith("QH")]
        return 3, "%s: %s" % (type(e).__name__, (qh or lines or ["?"])[0])
    sec = time.perf_counter() - t
    s = np.ascontiguousarray(d.simplices, dtype="<u4")
    with open(out, "wb") as f:
        f.write(b"DTLA"); f.write(struct.pack("<dQ", sec, 0)); f.write(struct.pack("<Q", s.shape[0])); f.write(s.tobytes())
    return 0, ""

if sys.argv[1] == "--version":
    print("scipy %s (numpy %s)" % (scipy.__version__, np.__version__)); sys.exit(0)
if sys.argv[1] == "--serve":
    reply = os.fdopen(3, "w")
    for line in sys.stdin:
        parts = line.rstrip("\n").split("\t")
        try:
            code, msg = run(*parts) if len(parts) == 2 else (2, "bad request")
        except Exception as e:
            code, msg = 3, "%s: %s" % (type(e).__name__, e)
        sys.stdout.flush(); sys.stderr.flush()
        reply.write("%d %s\n" % (code, " ".join(msg.split()))); reply.flush()
    sys.exit(0)
code, msg = run(sys.argv[1], sys.argv[2])
if msg:
    print(msg, file=sys.stderr)
sys.exit(code)
)PY";

}  // namespace

const std::vector<std::string>& peer_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const PeerSpec& p : kPeers) v.emplace_back(p.name);
    return v;
  }();
  return names;
}

bool is_builtin_peer_name(const std::string& name) { return find_peer(name).has_value(); }

bool is_peer_name(const std::string& name) {
  return is_builtin_peer_name(name) || find_command_peer(name).has_value() || is_function_peer(name);
}

std::vector<std::string> expand_peer_names(const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (const std::string& n : names) {
    if (n == "all") {
      for (const auto& p : peer_names())
        if (std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
      for (const auto& p : command_peer_names())
        if (std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
      continue;
    }
    if (!is_peer_name(n)) {
      std::string list;
      for (const auto& p : peer_names()) list += (list.empty() ? "" : ", ") + p;
      for (const auto& p : command_peer_names()) list += ", " + p;
      throw std::invalid_argument("unknown peer '" + n + "' (all, " + list + ")");
    }
    if (std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
  }
  return out;
}

std::string peer_binary(const PeerOptions& options, const std::string& name) {
  if (!options.peer_binary.empty()) return options.peer_binary;
  const bool gmsh = name.rfind("gmsh", 0) == 0;
  if (const char* env = std::getenv(gmsh ? "DTLAB_PEER_GMSH" : "DTLAB_PEER"); env && *env) return env;
  return gmsh ? DTLAB_PEER_GMSH_BINARY : DTLAB_PEER_BINARY;
}

PeerRun run_peer(const std::string& name, std::span<const Point3> points, const PeerOptions& options) {
  if (const auto command = find_command_peer(name); command && !is_builtin_peer_name(name))
    return run_command_peer(*command, points, options);
  if (is_function_peer(name)) return run_function_peer(name, points, options);
  const auto spec = find_peer(name);
  if (!spec) throw std::invalid_argument("unknown peer '" + name + "'");
  PeerRun run;
  run.name = name;
  TempDir dir("dtlab-peer");
  const std::string log = dir.file("log.txt");
  const ChildLimits limits = peer_limits(options, log, spec->runner == Runner::helper);
  const std::vector<Point3> pts(points.begin(), points.end());

  if (spec->runner == Runner::tetgen) {
    TetgenOutput t = run_tetgen(pts, options.tetgen, name == "tetgen-flip" ? "-QzJNFl" : "-QzJNF", dir, limits);
    if (auto v = child_failure(t.child, log, run)) {
      run.verdict = *v;
      return run;
    }
    run.message.clear();  // TetGen prints "Opening in.node." even with -Q
    if (!t.read_error.empty()) {
      run.verdict = Verdict::refused;
      run.message = "unreadable .ele: " + t.read_error;
      return run;
    }
    if (!t.wrote_ele) {
      // Our input spans a volume (dtlab refuses flat inputs first): no .ele is no answer.
      run.verdict = Verdict::refused;
      run.message = "wrote no .ele (exit 0 without an answer)";
      return run;
    }
    PeerAnswer a;
    a.seconds = t.child.seconds;
    a.tets = std::move(t.tets);
    adapt_and_judge(points, a, spec->orientation, options.check, options.threads, run);
    return run;
  }

  const std::string in = dir.file("in.bin"), out = dir.file("out.bin");
  write_peer_points(in, pts);
  std::vector<std::string> argv;
  if (spec->runner == Runner::python)
    argv = {options.python, "-c", kScipyScript};
  else
    argv = {peer_binary(options, name)};
  ChildResult c;
  if (options.servers && spec->slow_start) {
    argv.push_back("--serve");
    if (spec->runner == Runner::helper) argv.push_back(name);
    if (spec->threaded) argv.push_back(std::to_string(thread_count(options.threads)));
    std::string reply;
    c = options.servers->get(name, argv, limits).ask(in + "\t" + out, limits.timeout_s, reply);
    write_text_file(log, reply + "\n");  // where child_failure looks for the message
  } else {
    if (spec->runner == Runner::helper) argv.push_back(name);
    argv.insert(argv.end(), {in, out});
    if (spec->threaded) argv.push_back(std::to_string(thread_count(options.threads)));
    c = run_child(argv, limits);
  }
  if (auto v = child_failure(c, log, run)) {
    run.verdict = *v;
    return run;
  }
  PeerAnswer a;
  try {
    a = read_peer_answer(out);
  } catch (const std::exception& e) {
    run.verdict = Verdict::refused;
    run.message = std::string("no readable answer: ") + e.what();
    return run;
  }
  run.seconds = a.seconds;
  adapt_and_judge(points, a, spec->orientation, options.check, options.threads, run);
  return run;
}

std::string peer_version(const std::string& name, const PeerOptions& options) {
  if (const auto command = find_command_peer(name); command && !is_builtin_peer_name(name))
    return "command: " + command_text(command->argv);
  const auto spec = find_peer(name);
  if (!spec) throw std::invalid_argument("unknown peer '" + name + "'");
  TempDir dir("dtlab-peer");
  const std::string log = dir.file("log.txt");
  ChildLimits limits;
  limits.timeout_s = 60;
  limits.log_path = log;
  ChildResult c;
  if (spec->runner == Runner::tetgen) {
    // TetGen has no version switch (its -h ends in an uncaught exception): ask dpkg.
    c = run_child({options.tetgen, "-h"}, limits);
    if (c.status == ChildStatus::not_started) return "not installed";
    c = run_child({"dpkg-query", "-W", "-f=${Version}\\n", "tetgen"}, limits);
    const std::string v = c.status == ChildStatus::exited && c.exit_code == 0 ? last_line_of(log) : "";
    return "TetGen " + (v.empty() ? std::string("(version unknown)") : v) + (name == "tetgen-flip" ? " -l" : "");
  }
  if (spec->runner == Runner::python)
    c = run_child({options.python, "-c", kScipyScript, "--version"}, limits);
  else
    c = run_child({peer_binary(options, name), "--version", name}, limits);
  if (c.status != ChildStatus::exited || c.exit_code != 0) return "not installed";
  return last_line_of(log);
}

}  // namespace dtlab
