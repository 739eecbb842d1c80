#pragma once
// A line of text without its surrounding blanks: trailing spaces, tabs and newlines,
// leading spaces and tabs (the report and run-environment readers).
#include <cstddef>
#include <string>

namespace dtlab {

inline std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '\t')) s.pop_back();
  std::size_t i = 0;
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
  return s.substr(i);
}

}  // namespace dtlab
