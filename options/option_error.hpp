#pragma once
// A bad option value: "--name: reason", the line the CLI prints (exit 2) and the
// message of the Python module's ValueError.
#include <stdexcept>
#include <string>

namespace dtlab {

class OptionError : public std::invalid_argument {
 public:
  OptionError(const std::string& option, const std::string& reason)
      : std::invalid_argument(option + ": " + reason), option_(option), reason_(reason) {}
  const std::string& option() const { return option_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string option_, reason_;
};

}  // namespace dtlab
