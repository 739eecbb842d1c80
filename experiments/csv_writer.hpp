#pragma once
// The one CSV writer of the experiments' data files: comma-separated, one record per
// line, a field quoted when it holds a comma, a quote or a line break (quotes doubled,
// a line break written as a blank, so that every record stays on one line).
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace dtlab::experiments {

// One field as written: `s` itself, or `"s"` with its quotes doubled.
std::string csv_escape(std::string_view s);

// Writes the header and the rows (each field through csv_escape) to `file`, atomically.
void write_csv(const std::filesystem::path& file, const std::vector<std::string>& header,
               const std::vector<std::vector<std::string>>& rows);

}  // namespace dtlab::experiments
