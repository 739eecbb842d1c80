#pragma once
// Line-oriented tokenizer shared by the text readers: skips blank lines and
// '#' comments, parses numbers strictly, and reports errors as file:line.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <istream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/input_buffer.hpp"
#include "kernel/input_error.hpp"
#include "kernel/input_file.hpp"
#include "kernel/parse_number.hpp"

namespace dtlab {

class LineReader {
 public:
  explicit LineReader(std::string path)
      : path_(std::move(path)), bytes_(input_file_size(path_)), buf_(open_input_buffer(path_)) {
    in_.rdbuf(buf_.get());
  }

  // Next non-empty, non-comment line split into tokens; false at end of file. A read
  // error (the stream's bad state: an I/O error, or no memory for a huge line) is an
  // error, never the end. A line of more than `max_tokens` fields is an error before
  // it is split further; so is a line where ',' separates some fields and blanks
  // others ("0,5 0,5 0,5": a decimal comma, not six numbers).
  bool next(std::vector<std::string_view>& tokens, std::size_t max_tokens = SIZE_MAX) {
    while (std::getline(in_, line_)) {
      ++line_no_;
      std::string_view s(line_);
      if (line_no_ == 1 && s.substr(0, 3) == "\xEF\xBB\xBF") s.remove_prefix(3);  // a UTF-8 byte order mark
      if (auto hash = s.find('#'); hash != std::string_view::npos) s = s.substr(0, hash);
      split(s, tokens, max_tokens);
      if (!tokens.empty()) return true;
    }
    if (in_.bad() || (in_.fail() && !in_.eof()))
      throw InputError(path_, line_no_ + 1, "read error (an I/O error, or a line too long for the memory)");
    return false;
  }

  double to_double(std::string_view tok) const {
    double v = 0;
    if (std::string why = parse_double(tok, v); !why.empty()) fail(why);
    return v;
  }

  long to_long(std::string_view tok) const {
    long v = 0;
    if (std::string why = parse_long(tok, v); !why.empty()) fail(why);
    return v;
  }

  // A record count from a header: at least 0, and no more records of `min_tokens`
  // tokens than the file's size can hold (so no reservation of what is not there).
  long to_count(std::string_view tok, int min_tokens, const char* what) const {
    const long n = to_long(tok);
    if (n < 0) fail(std::string("negative ") + what + " count");
    if (!count_fits(n, min_tokens, bytes_))
      fail(std::string(what) + " count too large: " + quote_token(tok) + " in a file of " +
           std::to_string(*bytes_) + " bytes");
    return n;
  }

  [[noreturn]] void fail(const std::string& reason) const {
    throw InputError(path_, line_no_, reason);
  }
  long line() const { return line_no_; }
  const std::string& path() const { return path_; }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == ','; }

  void split(std::string_view s, std::vector<std::string_view>& tokens, std::size_t max_tokens) const {
    tokens.clear();
    bool comma_separated = false, blank_separated = false;
    std::size_t i = 0;
    while (i < s.size()) {
      const std::size_t gap = i;
      while (i < s.size() && is_space(s[i])) ++i;
      if (i == s.size()) break;
      if (!tokens.empty()) {
        const bool comma = s.substr(gap, i - gap).find(',') != std::string_view::npos;
        (comma ? comma_separated : blank_separated) = true;
      }
      std::size_t j = i;
      while (j < s.size() && !is_space(s[j])) ++j;
      if (tokens.size() == max_tokens) fail("more than " + std::to_string(max_tokens) + " fields on one line");
      tokens.push_back(s.substr(i, j - i));
      i = j;
    }
    if (comma_separated && blank_separated)
      fail("',' separates some fields and blanks others (a decimal comma? write 0.5, not 0,5)");
  }
  std::string path_;
  std::optional<std::uintmax_t> bytes_;
  std::unique_ptr<std::filebuf> buf_;  // a file's, or a FIFO's (kernel/input_buffer.hpp)
  std::istream in_{nullptr};
  std::string line_;
  long line_no_ = 0;
};

}  // namespace dtlab
