#include "experiments/csv_writer.hpp"

#include <sstream>

#include "kernel/output_file.hpp"

namespace dtlab::experiments {

std::string csv_escape(std::string_view s) {
  if (s.find_first_of(",\"\n\r") == std::string_view::npos) return std::string(s);
  std::string o = "\"";
  for (char c : s) o += c == '"' ? std::string("\"\"") : c == '\n' || c == '\r' ? std::string(" ") : std::string(1, c);
  return o + "\"";
}

namespace {
void write_record(std::ostream& out, const std::vector<std::string>& fields) {
  for (std::size_t i = 0; i < fields.size(); ++i) out << (i ? "," : "") << csv_escape(fields[i]);
  out << "\n";
}
}  // namespace

void write_csv(const std::filesystem::path& file, const std::vector<std::string>& header,
               const std::vector<std::vector<std::string>>& rows) {
  std::ostringstream out;
  write_record(out, header);
  for (const auto& r : rows) write_record(out, r);
  write_text_file(file.string(), out.str());
}

}  // namespace dtlab::experiments
