#pragma once
// A campaign's results file (JSON lines), opened for appending under an exclusive
// lock: a second campaign writing the same file at the same time is refused, and a
// last line cut by a kill (no newline at its end) is removed before anything is
// appended, so that its case runs again and nothing is lost or counted twice.
#include <string>

namespace dtlab::fuzz {

class ResultsLog {
 public:
  // Throws std::invalid_argument when another process holds the lock,
  // std::runtime_error when the file cannot be opened or repaired.
  explicit ResultsLog(std::string path);
  ~ResultsLog();
  ResultsLog(const ResultsLog&) = delete;
  ResultsLog& operator=(const ResultsLog&) = delete;

  // Appends whole lines in one write; throws std::runtime_error on failure.
  void append(const std::string& lines);
  const std::string& path() const { return path_; }

 private:
  void drop_cut_line();
  std::string path_;
  int fd_ = -1;
};

}  // namespace dtlab::fuzz
