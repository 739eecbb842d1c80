#pragma once
// A command's outputs as one set (kernel/output_file.hpp, remove_output_set): before
// anything is computed, no output may be one of the run's input files (the run would
// replace what it reads: `voronoi S.obj --out S`, `fracture DIR/pieces.obj --out DIR`,
// `--png` onto the input); before the first new file, the old members of the set go,
// with a note on stderr for each old file that this run does not write again (it is gone,
// not left stale beside the new set); inputs are never removed.
#include <sys/stat.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli_error.hpp"
#include "kernel/exit_guard.hpp"
#include "kernel/input_error.hpp"
#include "kernel/output_file.hpp"

namespace dtlab::cli {

struct OutputSet {
  std::vector<std::string> written;  // what this run writes
  std::vector<std::string> others;   // the set's other members (older runs' options)
  std::vector<std::string> inputs;   // the run's input files: never written, never removed
};

// A path and, when it exists, its file (device and inode): two paths name one file when
// they are equal or both exist as the same file (through any link).
struct PathFile {
  explicit PathFile(std::string p) : path(std::move(p)) { exists = !path.empty() && stat(path.c_str(), &st) == 0; }
  bool same(const PathFile& o) const { return path == o.path || (exists && o.exists && same_file(st, o.st)); }
  std::string path;
  struct stat st {};
  bool exists = false;
};

// Exit 2 (InputError naming the output) when an output is an input file or two outputs
// are one file (`--png` onto a member of `--out`'s set).
inline void refuse_overwriting_inputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) {
  std::vector<PathFile> in, out;
  for (const std::string& p : inputs)
    if (!p.empty()) in.emplace_back(p);
  for (const std::string& p : outputs) {
    if (p.empty()) continue;
    const PathFile o(p);
    for (const PathFile& i : in)
      if (o.exists && o.same(i))
        throw InputError(
            p, 0, "is the input file " + i.path + ": the run would replace what it reads (choose another output)");
    for (const PathFile& e : out)
      if (o.same(e)) throw InputError(p, 0, "written twice by this run (two options name it)");
    out.push_back(o);
  }
}

inline void remove_old_outputs(const OutputSet& set, bool quiet) {
  std::vector<std::string> all = set.written;
  all.insert(all.end(), set.others.begin(), set.others.end());
  std::vector<std::string> gone;
  for (const std::string& p : remove_output_set(all, set.inputs))
    for (const std::string& o : set.others)
      if (p == o) gone.push_back(p);
  if (quiet || gone.empty()) return;
  if (gone.size() == 1)
    std::fprintf(stderr, "note: removed %s of an earlier run (this run does not write it)\n", gone[0].c_str());
  else
    std::fprintf(stderr, "note: removed %zu files of an earlier run that this run does not write (%s, ...)\n",
                 gone.size(), gone[0].c_str());
}

// A set being written: each member this run puts in place is guarded from then until
// the last is (kernel/exit_guard.hpp), so an interrupt between two renames (a new
// PREFIX.node in place, its .ele not yet) removes the members already in place, and a
// failure on the way (an exception: a full disk) removes them too, each only while it
// is still the file this run wrote (the same inode). Only members missing when the
// writing starts are taken (the old set is gone by then): an input kept as an output (a
// 0-based .node) or a FIFO written in place is never removed.
class SetBeingWritten {
 public:
  // Removes the old set (remove_old_outputs); `written` the members to be placed.
  SetBeingWritten(const OutputSet& set, bool quiet) {
    remove_old_outputs(set, quiet);
    for (const std::string& p : set.written) {
      struct stat st {};
      if (!p.empty() && stat(p.c_str(), &st) != 0) new_.push_back(p);
    }
  }
  SetBeingWritten(const SetBeingWritten&) = delete;
  SetBeingWritten& operator=(const SetBeingWritten&) = delete;
  ~SetBeingWritten() {
    for (const auto& [path, st] : placed_) {
      struct stat now {};
      if (stat(path.c_str(), &now) == 0 && same_file(now, st)) ::unlink(path.c_str());
      release_path(path);
    }
  }
  // After each write: the members now in place, guarded from now on.
  void placed() {
    for (auto it = new_.begin(); it != new_.end();) it = take(it) ? new_.erase(it) : it + 1;
  }
  // The same for one member (a file of many, as each is placed: fracture's piece files).
  void placed(const std::string& member) {
    const auto it = std::find(new_.begin(), new_.end(), member);
    if (it != new_.end() && take(it)) new_.erase(it);
  }
  // The last member is in place: the set is the run's result.
  void done() {
    for (const auto& member : placed_) release_path(member.first);
    placed_.clear();
  }

 private:
  // Guards *it when it is in place.
  bool take(std::vector<std::string>::iterator it) {
    struct stat st {};
    if (stat(it->c_str(), &st) != 0) return false;
    guard_path(*it);
    placed_.emplace_back(*it, st);
    return true;
  }

  std::vector<std::string> new_;
  std::vector<std::pair<std::string, struct stat>> placed_;
};

// CLI11's check of --out: an empty path names no file ("" would mean "no --out").
inline std::string non_empty_path(const std::string& path) { return path.empty() ? "an empty path names no file" : ""; }

// --out PREFIX (tetra, voronoi; not empty: non_empty_path): a prefix of file names, so
// neither ending in '/' nor an existing folder (`--out d/` wrote hidden files d/.node and d/.ele).
inline void check_out_prefix(const std::string& prefix) {
  struct stat st {};
  if (prefix.back() == '/' || (stat(prefix.c_str(), &st) == 0 && S_ISDIR(st.st_mode)))
    throw UsageError("--out '" + prefix + "': expected a file prefix (PREFIX.node, ...), not a folder");
}

// --out DIR (fracture; not empty: non_empty_path): a folder, or a path where one can be made.
inline void check_out_folder(const std::string& dir) {
  struct stat st {};
  if (stat(dir.c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
    throw InputError(dir, 0, "--out: exists and is not a folder");
}

}  // namespace dtlab::cli
