#include "experiments/report.hpp"

#include <array>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include <sys/wait.h>

#include "dtlab/build_info.hpp"
#include "fuzz/rate_interval.hpp"
#include "fuzz/run_environment.hpp"
#include "kernel/output_file.hpp"
#include "kernel/trim.hpp"

#ifndef DTLAB_EXPERIMENTS_DIR
#define DTLAB_EXPERIMENTS_DIR "experiments"
#endif

namespace dtlab::experiments {

namespace fs = std::filesystem;

namespace {

// First line printed by a shell command, "" when it fails.
std::string shell_line(const std::string& command) {
  FILE* p = popen((command + " 2>/dev/null").c_str(), "r");
  if (!p) return "";
  std::array<char, 512> buf{};
  std::string out;
  if (std::fgets(buf.data(), static_cast<int>(buf.size()), p)) out = buf.data();
  pclose(p);
  return trim(out);
}

std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else o += c;
  }
  return o;
}

// `code`, **bold** and ![alt](src) inside one line (already escaped text around them).
std::string inline_html(const std::string& s) {
  std::string o;
  for (std::size_t i = 0; i < s.size();) {
    if (s[i] == '`') {
      const auto j = s.find('`', i + 1);
      if (j != std::string::npos) {
        o += "<code>" + html_escape(s.substr(i + 1, j - i - 1)) + "</code>";
        i = j + 1;
        continue;
      }
    }
    if (s.compare(i, 2, "**") == 0) {
      const auto j = s.find("**", i + 2);
      if (j != std::string::npos) {
        o += "<b>" + inline_html(s.substr(i + 2, j - i - 2)) + "</b>";
        i = j + 2;
        continue;
      }
    }
    // *emphasis* (a caption): a single star before a non-space, closed before a non-space
    if (s[i] == '*' && i + 1 < s.size() && s[i + 1] != '*' && s[i + 1] != ' ') {
      const auto j = s.find('*', i + 1);
      if (j != std::string::npos && s[j - 1] != ' ') {
        o += "<em>" + inline_html(s.substr(i + 1, j - i - 1)) + "</em>";
        i = j + 1;
        continue;
      }
    }
    if (s.compare(i, 2, "![") == 0) {
      const auto close = s.find("](", i);
      const auto end = close == std::string::npos ? close : s.find(')', close);
      if (end != std::string::npos) {
        o += "<img src=\"" + html_escape(s.substr(close + 2, end - close - 2)) + "\" alt=\"" +
             html_escape(s.substr(i + 2, close - i - 2)) + "\">";
        i = end + 1;
        continue;
      }
    }
    o += html_escape(std::string(1, s[i]));
    ++i;
  }
  return o;
}

std::vector<std::string> split_row(const std::string& line) {
  std::vector<std::string> cells;
  std::string t = trim(line);
  if (!t.empty() && t.front() == '|') t.erase(0, 1);
  if (!t.empty() && t.back() == '|') t.pop_back();
  std::stringstream ss(t);
  std::string cell;
  while (std::getline(ss, cell, '|')) cells.push_back(trim(cell));
  return cells;
}

}  // namespace

nlohmann::json machine_description() { return fuzz::machine_description(); }

nlohmann::json version_description() {
  nlohmann::json v = fuzz::build_description();
  v["python"] = shell_line("/usr/bin/python3 --version");
  v["matplotlib"] = shell_line("/usr/bin/python3 -c 'import matplotlib; print(matplotlib.__version__)'");
  return v;
}

nlohmann::json environment(const std::string& command_line, std::uint64_t seed) {
  return {{"command", command_line}, {"seed", seed}, {"machine", machine_description()},
          {"versions", version_description()}, {"date_utc", fuzz::utc_now()}};
}

std::string environment_markdown(const nlohmann::json& env) {
  std::ostringstream o;
  o << "## Reproduce\n\n```sh\n" << env.value("command", "") << "\n```\n\n";
  const auto& v = env["versions"];
  o << "Seed: `" << env.value("seed", 0) << "`. Run at " << env.value("date_utc", "") << " by dtlab "
    << v.value("dtlab", "") << ", commit `" << v.value("git_commit", "unknown") << "`.\n\n";
  o << "| | |\n| --- | --- |\n";
  const auto& m = env["machine"];
  o << "| CPU | " << m.value("cpu", "") << " |\n| hardware threads | " << m.value("hardware_threads", 0) << " |\n";
  o << "| memory | " << m.value("memory", "") << " |\n| OS kernel | " << m.value("kernel", "") << " |\n";
  for (const auto& [k, val] : env["versions"].items())
    o << "| " << k << " | " << (val.is_string() ? val.get<std::string>() : val.dump()) << " |\n";
  o << "\n";
  return o.str();
}

void write_text(const fs::path& file, const std::string& text) {
  write_text_file(file.string(), text);
}

int draw_figures(const fs::path& dir) {
  fs::path script = fs::path(DTLAB_EXPERIMENTS_DIR) / "plot_figures.py";
  if (const char* env = std::getenv("DTLAB_EXPERIMENTS_DIR")) script = fs::path(env) / "plot_figures.py";
  if (!fs::exists(script) || !fs::exists("/usr/bin/python3")) return -1;
  std::error_code ec;
  fs::copy_file(script, dir / "plot_figures.py", fs::copy_options::overwrite_existing, ec);
  const std::string cmd = "/usr/bin/python3 '" + (dir / "plot_figures.py").string() + "' '" + dir.string() +
                          "' > '" + (dir / "plot.log").string() + "' 2>&1";
  const int status = std::system(cmd.c_str());
  return status == 0 ? 0 : (WIFEXITED(status) ? WEXITSTATUS(status) : -1);
}

std::string markdown_to_html(const std::string& markdown, const std::string& title) {
  std::ostringstream o;
  o << "<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>" << html_escape(title) << "</title>\n"
    << "<style>body{font-family:sans-serif;max-width:1100px;margin:2em auto;line-height:1.4}"
       "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #bbb;padding:2px 8px;"
       "text-align:right}td:first-child,th:first-child{text-align:left}pre{background:#f4f4f4;"
       "padding:.6em;overflow-x:auto}img{max-width:100%}code{background:#f4f4f4}</style>\n</head><body>\n";
  std::istringstream in(markdown);
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  std::string para;
  auto flush_para = [&] {
    if (!trim(para).empty()) o << "<p>" << inline_html(trim(para)) << "</p>\n";
    para.clear();
  };
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    const std::string t = trim(l);
    if (t.rfind("```", 0) == 0) {
      flush_para();
      o << "<pre>";
      for (++i; i < lines.size() && trim(lines[i]).rfind("```", 0) != 0; ++i) o << html_escape(lines[i]) << "\n";
      o << "</pre>\n";
    } else if (t.rfind("#", 0) == 0) {
      flush_para();
      std::size_t level = 0;
      while (level < t.size() && t[level] == '#') ++level;
      o << "<h" << level << ">" << inline_html(trim(t.substr(level))) << "</h" << level << ">\n";
    } else if (t.rfind("|", 0) == 0) {
      flush_para();
      o << "<table>\n";
      bool header = true;
      for (; i < lines.size() && trim(lines[i]).rfind("|", 0) == 0; ++i) {
        const auto cells = split_row(lines[i]);
        if (!cells.empty() && cells[0].find("---") != std::string::npos) continue;
        o << "<tr>";
        for (const auto& c : cells) o << (header ? "<th>" : "<td>") << inline_html(c) << (header ? "</th>" : "</td>");
        o << "</tr>\n";
        header = false;
      }
      --i;
      o << "</table>\n";
    } else if (t.rfind("- ", 0) == 0) {
      flush_para();
      o << "<ul>\n";
      for (; i < lines.size() && trim(lines[i]).rfind("- ", 0) == 0; ++i) {
        std::string item = trim(lines[i]).substr(2);
        // continuation lines of a list item are indented
        while (i + 1 < lines.size() && lines[i + 1].rfind("  ", 0) == 0 && !trim(lines[i + 1]).empty() &&
               trim(lines[i + 1]).rfind("- ", 0) != 0)
        {
          item += ' ';  // (not `" " + ...`: GCC 12 warns falsely on that, -Wrestrict)
          item += trim(lines[++i]);
        }
        o << "<li>" << inline_html(item) << "</li>\n";
      }
      --i;
      o << "</ul>\n";
    } else if (t.empty()) {
      flush_para();
    } else {
      para += " " + t;
    }
  }
  flush_para();
  o << "</body></html>\n";
  return o.str();
}

std::string table_row(const std::vector<std::string>& cells) {
  std::string s = "|";
  for (const auto& c : cells) s += " " + c + " |";
  return s + "\n";
}

std::string table_rule(std::size_t columns, std::size_t left_aligned) {
  std::string s = "|";
  for (std::size_t i = 0; i < columns; ++i) s += i < left_aligned ? " --- |" : " ---: |";
  return s + "\n";
}

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string rate_cell(std::size_t failed, std::size_t cases) {
  return fuzz::rate_text(fuzz::wilson_interval(failed, cases));
}

std::string timing_claim(const Timing& a, const Timing& b) {
  char ranges[160];
  std::snprintf(ranges, sizeof ranges, "median %.4f s [%.4f, %.4f] vs %.4f s [%.4f, %.4f], %d and %d runs", a.median,
                a.min, a.max, b.median, b.min, b.max, a.runs, b.runs);
  const double spread = std::max(a.max - a.min, b.max - b.min);
  if (a.runs < 2 || b.runs < 2) return fmt("%.2fx", a.median / b.median) + " (" + ranges + "; one run: no spread known)";
  if (std::abs(a.median - b.median) <= spread) return std::string("no measurable difference (") + ranges + ")";
  return fmt("%.2fx", a.median / b.median) + " (" + ranges + ")";
}

std::string figure_markdown(const fs::path& dir, const std::string& file, const std::string& caption) {
  if (fs::exists(dir / file)) return "![" + caption + "](" + file + ")\n\n*" + caption + "*\n\n";
  return "(figure `" + file + "` not drawn: see plot.log; the data is in `data/`)\n\n";
}

}  // namespace dtlab::experiments
