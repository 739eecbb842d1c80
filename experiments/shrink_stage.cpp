#include "experiments/shrink_stage.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>

#include "fuzz/work_queue.hpp"
#include "oracle/peers/served_child.hpp"

namespace dtlab::experiments {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Sets of served helpers lent to the running pairs and kept across pairs and passes,
// so that a helper starts about once per peer and worker.
class HelperPool {
 public:
  std::unique_ptr<ServedChildren> take() {
    std::lock_guard<std::mutex> g(lock_);
    if (free_.empty()) return std::make_unique<ServedChildren>();
    auto s = std::move(free_.back());
    free_.pop_back();
    return s;
  }
  void give_back(std::unique_ptr<ServedChildren> s) {
    std::lock_guard<std::mutex> g(lock_);
    free_.push_back(std::move(s));
  }

 private:
  std::mutex lock_;
  std::vector<std::unique_ptr<ServedChildren>> free_;
};

bool shrinks_hang(const ShrinkPair& p) { return p.failure->run.verdict == Verdict::hung && p.hung_try_seconds > 0; }

// Another pass can get it further: stopped by its time share or its run budget.
bool unfinished(const PeerCase& c) { return !c.shrunk_minimal && (c.shrink_stop == "time" || c.shrink_stop == "runs"); }

}  // namespace

double hung_try_limit(double slowest_answered_seconds, double full_limit_seconds) {
  return std::min(std::max(2.0, 10 * slowest_answered_seconds), full_limit_seconds / 2);
}

ShrinkStageResult run_shrink_stage(std::vector<ShrinkPair>& pairs, const ShrinkStageOptions& o) {
  const auto t0 = Clock::now();
  ShrinkStageResult result;
  const unsigned jobs = std::max(1u, o.jobs);
  const double full_limit = o.peer_options.timeout_s;
  // Each shrunk hang needs one run that may last the full limit, `jobs` at a time, and
  // a confirming run starts only when it can end within the stage: 2 s more per round
  // for starting and judging, and for passes that end a little late.
  const auto hangs = static_cast<std::size_t>(std::count_if(pairs.begin(), pairs.end(), shrinks_hang));
  result.reserved_seconds =
      hangs ? std::min(o.seconds / 2, (full_limit + 2) * std::ceil(double(hangs) / jobs)) : 0.0;
  const double passes_end = o.seconds - result.reserved_seconds;
  HelperPool helpers;

  std::vector<ShrinkPair*> todo;
  for (ShrinkPair& p : pairs) todo.push_back(&p);
  while (!todo.empty() && result.pass_seconds.size() < o.max_passes) {
    // A later pass needs a second per pair at least to get anywhere.
    if (!result.pass_seconds.empty() && passes_end - seconds_since(t0) < double(todo.size()) / jobs) break;
    const auto pass_t0 = Clock::now();
    std::atomic<std::size_t> pairs_left{todo.size()};
    std::atomic<bool> progress{false};
    fuzz::run_work_queue(todo.size(), jobs, [&](std::size_t i) {
      ShrinkPair& p = *todo[i];
      PeerCase& c = *p.failure;
      const double left = std::max(0.0, passes_end - seconds_since(t0));
      const double share = std::min(left, left * jobs / double(std::max<std::size_t>(pairs_left--, 1)));
      const std::size_t points_before = c.shrunk_input.empty() ? p.points.size() : c.shrunk_input.size();
      const fuzz::ShrinkPosition position_before = c.shrink_position;
      auto servers = helpers.take();
      // With no time left a pair still gets its input saved (its share spent at once).
      shrink_pass(c, p.points, o.peer_options, {o.runs_per_pass, std::max(share, 1e-9), p.hung_try_seconds},
                  servers.get());
      helpers.give_back(std::move(servers));
      if (c.shrunk_minimal || c.shrunk_points < points_before || c.shrink_position > position_before)
        progress = true;
    });
    result.pass_seconds.push_back(seconds_since(pass_t0));
    result.pass_pairs.push_back(todo.size());
    std::vector<ShrinkPair*> next;
    for (ShrinkPair* p : todo)
      if (unfinished(*p->failure)) next.push_back(p);
    todo = std::move(next);
    if (!progress) break;
  }

  // The shrunk hangs, each run once under the full limit in a fresh process.
  const auto confirm_t0 = Clock::now();
  std::vector<ShrinkPair*> to_confirm;
  for (ShrinkPair& p : pairs)
    if (shrinks_hang(p) && p.failure->shrunk_points < p.points.size()) to_confirm.push_back(&p);
  fuzz::run_work_queue(to_confirm.size(), jobs, [&](std::size_t i) {
    confirm_hang(*to_confirm[i]->failure, to_confirm[i]->points, o.peer_options, o.seconds - seconds_since(t0));
  });
  result.confirm_seconds = seconds_since(confirm_t0);
  for (ShrinkPair& p : pairs) save_shrunk(*p.failure, p.points.size(), o.out_dir, p.command);
  result.seconds = seconds_since(t0);
  return result;
}

}  // namespace dtlab::experiments
