#pragma once
// A whole file in memory, read either as text tokens (with line numbers) or as
// binary little/big-endian scalars. Shared by the PLY and STL readers.
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <istream>
#include <iterator>
#include <string>
#include <string_view>

#include "kernel/input_buffer.hpp"
#include "kernel/input_error.hpp"
#include "kernel/input_file.hpp"
#include "kernel/parse_number.hpp"

namespace dtlab::detail {

class ByteSource {
 public:
  explicit ByteSource(std::string path) : path_(std::move(path)) {
    input_file_size(path_);  // names a missing file or a directory
    const auto buf = open_input_buffer(path_);  // a FIFO waits for its writer at most DTLAB_FIFO_WAIT s
    std::istream in(buf.get());                 // a read error sets badbit (libstdc++'s filebuf throws)
    data_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (in.bad()) throw InputError(path_, 0, "read error");
  }
  const std::string& path() const { return path_; }
  std::size_t size() const { return data_.size(); }
  std::size_t pos() const { return pos_; }
  const std::string& data() const { return data_; }
  // Lines consumed so far: after next_line, the 1-based number of that line.
  long line() const { return line_; }
  bool at_end() const { return pos_ >= data_.size(); }
  // Text formats: a UTF-8 byte order mark at the start is skipped (as line_reader does).
  void skip_text_bom() {
    if (pos_ == 0 && data_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ = 3;
  }

  // Next full line without its terminator ("\n" or "\r\n"); false at end of file.
  bool next_line(std::string_view& out) {
    if (at_end()) return false;
    std::size_t e = data_.find('\n', pos_);
    if (e == std::string::npos) e = data_.size();
    out = std::string_view(data_).substr(pos_, e - pos_);
    if (!out.empty() && out.back() == '\r') out.remove_suffix(1);
    pos_ = e + 1;
    ++line_;
    return true;
  }

  // Next whitespace-separated token, crossing lines; false at end of file.
  bool next_token(std::string_view& out) {
    for (;;) {
      while (pos_ < data_.size() && (data_[pos_] == ' ' || data_[pos_] == '\t' || data_[pos_] == '\r'))
        ++pos_;
      if (pos_ >= data_.size()) return false;
      if (data_[pos_] == '\n') {
        ++pos_;
        ++line_;
        continue;
      }
      break;
    }
    token_line_ = line_ + 1;
    const std::size_t b = pos_;
    while (pos_ < data_.size() && !std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
    out = std::string_view(data_).substr(b, pos_ - b);
    return true;
  }
  // 1-based line of the last token read.
  long token_line() const { return token_line_; }

  double parse_double(std::string_view tok, long line) const {
    double v = 0;
    if (std::string why = dtlab::parse_double(tok, v); !why.empty()) throw InputError(path_, line, why);
    return v;
  }

  // Copies n raw bytes, swapping them when the file's byte order differs from ours.
  void read_raw(void* dst, std::size_t n, bool big_endian, const char* what) {
    if (data_.size() - pos_ < n || pos_ > data_.size())
      throw InputError(path_, 0, std::string("file truncated while reading ") + what);
    unsigned char buf[8];
    std::memcpy(buf, data_.data() + pos_, n);
    if (big_endian != (std::endian::native == std::endian::big))
      for (std::size_t i = 0; i < n / 2; ++i) std::swap(buf[i], buf[n - 1 - i]);
    std::memcpy(dst, buf, n);
    pos_ += n;
  }
  void skip(std::size_t n) {
    if (data_.size() - pos_ < n) throw InputError(path_, 0, "file truncated");
    pos_ += n;
  }

 private:
  std::string path_;
  std::string data_;
  std::size_t pos_ = 0;
  long line_ = 0;
  long token_line_ = 0;
};

}  // namespace dtlab::detail
