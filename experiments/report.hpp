#pragma once
// The pieces every experiment report shares: the report folder, the environment
// (machine, versions, command line), the figure script and the Markdown -> HTML step.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dtlab::experiments {

// CPU model, core count and memory from /proc/cpuinfo and /proc/meminfo.
nlohmann::json machine_description();
// dtlab, compiler, CGAL and TetGen versions, git commit when the source tree has one.
nlohmann::json version_description();

// Runs `/usr/bin/python3 plot_figures.py DIR` (the script is copied into DIR first,
// so the report holds the code that drew it). Returns the script's exit status
// (-1: no python or script); its output goes to DIR/plot.log.
int draw_figures(const std::filesystem::path& dir);

// Minimal Markdown (headings, paragraphs, lists, pipe tables, code blocks, images,
// `code`, **bold**) to a standalone HTML page.
std::string markdown_to_html(const std::string& markdown, const std::string& title);

void write_text(const std::filesystem::path& file, const std::string& text);

// The environment section of a report (Markdown) and its JSON twin.
std::string environment_markdown(const nlohmann::json& env);
nlohmann::json environment(const std::string& command_line, std::uint64_t seed);

// "| a | b |" rows from cells.
std::string table_row(const std::vector<std::string>& cells);
std::string table_rule(std::size_t columns, std::size_t left_aligned = 1);
std::string fmt(const char* format, double v);

// A failure rate as the reports print it: "91.0% [82.4, 95.9] (58/64)": percent, the
// 95% Wilson interval, failures / cases.
std::string rate_cell(std::size_t failed, std::size_t cases);

// A timing comparison from repeated runs: "1.37x (median 0.0610 s [0.0511, 0.0740] vs
// 0.0446 s [0.0399, 0.0497])", or "no measurable difference (...)" when the spread of
// either side's runs (max - min) is at least the difference of the medians.
struct Timing {
  double median = 0, min = 0, max = 0;
  int runs = 0;
};
std::string timing_claim(const Timing& a, const Timing& b);

// A figure line `![caption](file)` if DIR/file exists, else a note that it is missing.
std::string figure_markdown(const std::filesystem::path& dir, const std::string& file,
                            const std::string& caption);

}  // namespace dtlab::experiments
