#pragma once
// A defect in an input file: reported as "file:line: reason" and exit code 2.
#include <stdexcept>
#include <string>

namespace dtlab {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, long line, std::string reason)
      : std::runtime_error(file + ":" + std::to_string(line) + ": " + reason),
        file_(std::move(file)), line_(line), reason_(std::move(reason)) {}
  const std::string& file() const { return file_; }
  long line() const { return line_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string file_;
  long line_;
  std::string reason_;
};

}  // namespace dtlab
