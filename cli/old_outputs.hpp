#pragma once
// The old set of a command's outputs removed before the new one is written
// (kernel/output_file.hpp, remove_output_set), with a note on stderr for each old file
// that this run does not write again: it is gone, not left stale beside the new set.
#include <cstdio>
#include <string>
#include <vector>

#include "kernel/output_file.hpp"

namespace dtlab::cli {

struct OutputSet {
  std::vector<std::string> written;  // what this run writes
  std::vector<std::string> others;   // the set's other members (older runs' options)
  std::string keep;                  // a file to keep even when it is a member (the input)
};

inline void remove_old_outputs(const OutputSet& set, bool quiet) {
  std::vector<std::string> all = set.written;
  all.insert(all.end(), set.others.begin(), set.others.end());
  std::vector<std::string> gone;
  for (const std::string& p : remove_output_set(all, set.keep))
    for (const std::string& o : set.others)
      if (p == o) gone.push_back(p);
  if (quiet || gone.empty()) return;
  if (gone.size() == 1)
    std::fprintf(stderr, "note: removed %s of an earlier run (this run does not write it)\n", gone[0].c_str());
  else
    std::fprintf(stderr, "note: removed %zu files of an earlier run that this run does not write (%s, ...)\n",
                 gone.size(), gone[0].c_str());
}

}  // namespace dtlab::cli
