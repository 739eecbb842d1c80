#include "oracle/peers/peers_file.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <variant>

#include <toml++/toml.h>
#include <nlohmann/json.hpp>

#include "kernel/input_error.hpp"
#include "oracle/peers/json_fields.hpp"

namespace dtlab {
namespace {

// One entry, whatever the format: its command as a string or argv words.
using CommandField = std::variant<std::string, std::vector<std::string>>;

// One entry of either kind, as the file gives it: where it is, its fields.
struct Entry {
  long line = 0;
  std::size_t index = 0;
  std::string name, kind;
  CommandField command;
};

// Adds the entry's peer to `out`, its template checked for its kind.
void add_entry(const std::string& path, const Entry& e, const VoronoiPeerCheck& voronoi_check, PeersFile& out) {
  const std::string where = "peer " + std::to_string(e.index + 1) + ": ";
  if (e.kind != "delaunay" && e.kind != "voronoi")
    throw InputError(path, e.line, where + "unknown kind '" + e.kind + "' (delaunay, voronoi)");
  try {
    std::vector<std::string> argv = std::holds_alternative<std::string>(e.command)
                                        ? split_command(std::get<std::string>(e.command))
                                        : std::get<std::vector<std::string>>(e.command);
    if (e.kind == "voronoi")
      out.voronoi.push_back(voronoi_check(e.name, std::move(argv)));
    else
      out.delaunay.push_back(make_command_peer(e.name, std::move(argv)));
  } catch (const std::invalid_argument& x) {
    throw InputError(path, e.line, where + x.what());
  }
}

std::string read_whole(const std::string& path) {
  if (std::filesystem::is_directory(path)) throw InputError(path, 0, "is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open file");
  std::stringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path, 0, "read error");
  return text.str();
}

const char* const kFields = "(name, command, kind)";

bool known_field(const std::string& key) { return key == "name" || key == "command" || key == "kind"; }

PeersFile read_json(const std::string& path, const std::string& s, const VoronoiPeerCheck& voronoi_check) {
  const auto line_of = [&](std::size_t byte) {
    return 1 + static_cast<long>(std::count(s.begin(), s.begin() + static_cast<long>(std::min(byte, s.size())), '\n'));
  };
  nlohmann::json j;
  try {
    j = parse_unique_fields(s);
  } catch (const nlohmann::json::parse_error& e) {
    const std::string what = e.what();
    throw InputError(path, line_of(e.byte ? e.byte - 1 : 0), "not JSON: " + what.substr(what.find(':') + 2));
  } catch (const DuplicateField& e) {
    throw InputError(path, 0, e.what());
  }
  const nlohmann::json list = j.is_object() && j.contains("peers") ? j["peers"] : j;
  if (!list.is_array()) throw InputError(path, 1, "expected {\"peers\": [...]} or an array of peers");
  PeersFile peers;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const nlohmann::json& e = list[i];
    const std::string where = "peer " + std::to_string(i + 1) + ": ";
    if (!e.is_object() || !e.contains("name") || !e["name"].is_string() || !e.contains("command"))
      throw InputError(path, 0, where + "expected {\"name\": \"...\", \"command\": \"...\" or [...]}");
    for (const auto& [key, value] : e.items())
      if (!known_field(key)) throw InputError(path, 0, where + "unknown field '" + key + "' " + kFields);
    if (e.contains("kind") && !e["kind"].is_string())
      throw InputError(path, 0, where + "kind must be \"delaunay\" or \"voronoi\"");
    CommandField command;
    const nlohmann::json& c = e["command"];
    if (c.is_string())
      command = c.get<std::string>();
    else if (c.is_array() && std::all_of(c.begin(), c.end(), [](const nlohmann::json& a) { return a.is_string(); }))
      command = c.get<std::vector<std::string>>();
    else
      throw InputError(path, 0, where + "command must be a string or an array of strings");
    add_entry(path, {0, i, e["name"].get<std::string>(), e.value("kind", std::string("delaunay")), command},
              voronoi_check, peers);
  }
  return peers;
}

long line_of(const toml::node& n) { return static_cast<long>(n.source().begin.line); }

PeersFile read_toml(const std::string& path, const std::string& s, const VoronoiPeerCheck& voronoi_check) {
  toml::table root;
  try {
    root = toml::parse(s, path);
  } catch (const toml::parse_error& e) {
    throw InputError(path, static_cast<long>(e.source().begin.line), "not TOML: " + std::string(e.description()));
  }
  for (const auto& [key, value] : root)
    if (key.str() != "peers")
      throw InputError(path, line_of(value),
                       "unknown key '" + std::string(key.str()) + "' (one [[peers]] table per peer)");
  const toml::array* list = root["peers"].as_array();
  if (!list)
    throw InputError(path, root.contains("peers") ? line_of(*root.get("peers")) : 1,
                     "expected [[peers]] tables (name = \"...\", command = \"...\" or [...])");
  PeersFile peers;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::node& e = (*list)[i];
    const std::string where = "peer " + std::to_string(i + 1) + ": ";
    const toml::table* t = e.as_table();
    if (!t) throw InputError(path, line_of(e), where + "expected a table (name = \"...\", command = \"...\")");
    for (const auto& [key, value] : *t)
      if (!known_field(std::string(key.str())))
        throw InputError(path, line_of(value), where + "unknown field '" + std::string(key.str()) + "' " + kFields);
    const toml::node* kind = t->get("kind");
    if (kind && !kind->is_string())
      throw InputError(path, line_of(*kind), where + "kind must be \"delaunay\" or \"voronoi\"");
    const toml::node* name = t->get("name");
    const toml::node* command = t->get("command");
    if (!name || !name->is_string())
      throw InputError(path, name ? line_of(*name) : line_of(e), where + "needs name = \"...\" (a string)");
    if (!command) throw InputError(path, line_of(e), where + "needs command = \"...\" or [\"argv\", ...]");
    CommandField field;
    if (command->is_string()) {
      field = std::string(*command->value<std::string_view>());
    } else if (const toml::array* argv = command->as_array(); argv && argv->is_homogeneous(toml::node_type::string)) {
      std::vector<std::string> words;
      for (const toml::node& w : *argv) words.emplace_back(*w.value<std::string_view>());
      field = std::move(words);
    } else {
      throw InputError(path, line_of(*command), where + "command must be a string or an array of strings");
    }
    add_entry(path,
              {line_of(*command), i, std::string(*name->value<std::string_view>()),
               kind ? std::string(*kind->value<std::string_view>()) : "delaunay", field},
              voronoi_check, peers);
  }
  return peers;
}

bool is_toml(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".toml";
}

}  // namespace

PeersFile read_peers_file(const std::string& path, const VoronoiPeerCheck& voronoi_check) {
  const std::string text = read_whole(path);
  return is_toml(path) ? read_toml(path, text, voronoi_check) : read_json(path, text, voronoi_check);
}

}  // namespace dtlab
