#include "oracle/peers/peer_function.hpp"

#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "kernel/exit_guard.hpp"
#include "oracle/peers/peer_adapter.hpp"
#include "oracle/peers/peer_child.hpp"
#include "oracle/peers/peer_command.hpp"
#include "oracle/peers/temp_dir.hpp"

namespace dtlab {
namespace {

struct Registry {
  std::mutex lock;
  std::map<std::string, std::shared_ptr<const PeerFunction>> peers;
};

Registry& registry() {
  static Registry r;
  return r;
}

std::shared_ptr<const PeerFunction> find(const std::string& name) {
  Registry& r = registry();
  std::lock_guard<std::mutex> g(r.lock);
  const auto it = r.peers.find(name);
  return it == r.peers.end() ? nullptr : it->second;
}

// An index outside [0, n) is a wrong answer, named with the tet that holds it (as the
// .ele reader names a command peer's).
std::string index_error(const std::vector<std::array<std::int64_t, 4>>& tets, std::size_t n) {
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (std::int64_t v : tets[t])
      if (v < 0 || static_cast<std::uint64_t>(v) >= n)
        return "tet " + std::to_string(t) + " has vertex " + std::to_string(v) + ", not an index of the " +
               std::to_string(n) + " points (0-based)";
  return "";
}

}  // namespace

void register_function_peer(const std::string& name, PeerFunction run) {
  check_peer_name(name);
  if (is_builtin_peer_name(name)) throw std::invalid_argument("peer name '" + name + "' is a built-in peer's");
  if (find_command_peer(name)) throw std::invalid_argument("peer name '" + name + "' is a command peer's");
  Registry& r = registry();
  std::lock_guard<std::mutex> g(r.lock);
  if (!r.peers.emplace(name, std::make_shared<const PeerFunction>(std::move(run))).second)
    throw std::invalid_argument("peer '" + name + "' is already registered (by another call running now?)");
}

void unregister_function_peer(const std::string& name) {
  Registry& r = registry();
  std::lock_guard<std::mutex> g(r.lock);
  r.peers.erase(name);
}

bool is_function_peer(const std::string& name) { return find(name) != nullptr; }

PeerRun run_function_peer(const std::string& name, std::span<const Point3> points, const PeerOptions& options) {
  const auto function = find(name);
  if (!function) throw std::invalid_argument("unknown peer '" + name + "'");
  PeerRun run;
  run.name = name;
  TempDir dir("dtlab-peer");
  const std::string log = dir.file("log.txt");
  // A sanitizer build's forked interpreter holds the sanitizer's shadow reservation.
  const ChildLimits limits = peer_limits(options, log, true);
  // Started before the host forks: its fork handler gives the child PR_SET_PDEATHSIG,
  // so the child dies with the host even when the host is killed with SIGKILL.
  prepare_exit_guard();
  const FunctionAnswer a = (*function)(points, limits);
  if (const auto failure = child_failure(a.child, log, run, false)) {
    run.verdict = *failure;
    return run;
  }
  if (!a.answered) {
    run.verdict = Verdict::refused;
    run.message = "exited 0 without an answer" + (run.message.empty() ? "" : ": " + run.message);
    return run;
  }
  run.seconds = a.seconds;
  std::string wrong = a.bad_answer.empty() ? index_error(a.tets, points.size()) : a.bad_answer;
  if (!wrong.empty()) {
    run.verdict = Verdict::invalid;
    run.message = "wrong answer: " + wrong;
    return run;
  }
  PeerAnswer answer;
  answer.seconds = a.seconds;
  answer.tets.reserve(a.tets.size());
  for (const auto& t : a.tets)
    answer.tets.push_back({static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[1]),
                           static_cast<std::uint32_t>(t[2]), static_cast<std::uint32_t>(t[3])});
  adapt_and_judge(points, answer, PeerOrientation::by_sign, options.check, options.threads, run);
  return run;
}

}  // namespace dtlab
