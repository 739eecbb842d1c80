#pragma once
// The Python parameter that a CLI option is: the library's OptionError and the shared
// range checks name the CLI's "--eps-mode"; the Python module's messages name eps_mode.
#include <string>
#include <string_view>

namespace dtlab::python {

inline std::string parameter_name(std::string_view cli_option) {
  if (cli_option.starts_with("--")) cli_option.remove_prefix(2);
  std::string name(cli_option);
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

}  // namespace dtlab::python
