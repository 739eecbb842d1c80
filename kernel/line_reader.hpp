#pragma once
// Line-oriented tokenizer shared by the text readers: skips blank lines and
// '#' comments, parses numbers strictly, and reports errors as file:line.
#include <charconv>
#include <cmath>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/input_error.hpp"

namespace dtlab {

class LineReader {
 public:
  explicit LineReader(std::string path) : path_(std::move(path)), in_(path_) {
    if (!in_) throw InputError(path_, 0, "cannot open file");
  }

  // Next non-empty, non-comment line split into tokens; false at end of file.
  bool next(std::vector<std::string_view>& tokens) {
    while (std::getline(in_, line_)) {
      ++line_no_;
      tokens.clear();
      std::string_view s(line_);
      if (auto hash = s.find('#'); hash != std::string_view::npos) s = s.substr(0, hash);
      std::size_t i = 0;
      while (i < s.size()) {
        while (i < s.size() && is_space(s[i])) ++i;
        std::size_t j = i;
        while (j < s.size() && !is_space(s[j])) ++j;
        if (j > i) tokens.push_back(s.substr(i, j - i));
        i = j;
      }
      if (!tokens.empty()) return true;
    }
    return false;
  }

  double to_double(std::string_view tok) const {
    double v = 0;
    const char* b = tok.data();
    const char* e = b + tok.size();
    if (b != e && *b == '+') ++b;
    auto [p, ec] = std::from_chars(b, e, v);
    if (ec != std::errc() || p != e) fail("not a number: '" + std::string(tok) + "'");
    if (!std::isfinite(v)) fail("non-finite coordinate: '" + std::string(tok) + "'");
    return v;
  }

  long to_long(std::string_view tok) const {
    long v = 0;
    auto [p, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
    if (ec != std::errc() || p != tok.data() + tok.size())
      fail("not an integer: '" + std::string(tok) + "'");
    return v;
  }

  [[noreturn]] void fail(const std::string& reason) const {
    throw InputError(path_, line_no_, reason);
  }
  long line() const { return line_no_; }
  const std::string& path() const { return path_; }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == ','; }
  std::string path_;
  std::ifstream in_;
  std::string line_;
  long line_no_ = 0;
};

}  // namespace dtlab
