#pragma once
// A JSON parse that refuses an object naming a field twice. nlohmann keeps the last
// of two equal keys, so a second "cells" or "site" in a file a tool or a user wrote
// would replace the first without a word: the files dtlab reads from others (peer
// answers, peer lists) are parsed with parse_unique_fields instead.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace dtlab {

// Thrown by parse_unique_fields: `where` is the object's path from the root
// ("cells[3]", empty for the root), `field` the repeated name.
struct DuplicateField : std::runtime_error {
  DuplicateField(std::string w, std::string f)
      : std::runtime_error(message(w, f)), where(std::move(w)), field(std::move(f)) {}
  std::string where, field;

 private:
  static std::string message(const std::string& w, const std::string& f) {
    std::string m = w;
    if (!m.empty()) m.append(": ");
    m.append("duplicate field '").append(f).append("'");
    return m;
  }
};

namespace detail {

// Fed nlohmann's parse events; keeps the open containers only (their fields so far,
// or their elements so far, for the path).
class UniqueFields {
 public:
  bool operator()(int, nlohmann::json::parse_event_t event, const nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    if (event == E::object_start || event == E::array_start) {
      open_.push_back({event == E::object_start, {}, {}, 0});
    } else if (event == E::key) {
      Open& o = open_.back();
      const auto& key = parsed.get_ref<const std::string&>();
      // A linear search while the object is small (a cell's five fields), a hash set past
      // kSmall: an object of 10^5 fields would otherwise cost 10^10 compares.
      const bool seen = o.fields.size() < kSmall ? std::find(o.fields.begin(), o.fields.end(), key) != o.fields.end()
                                                 : !o.wide.insert(key).second;
      if (seen) throw DuplicateField(path(), key);
      o.fields.push_back(key);
      if (o.fields.size() == kSmall) o.wide.insert(o.fields.begin(), o.fields.end());
    } else if (event == E::object_end || event == E::array_end) {
      open_.pop_back();
      element_done();
    } else if (event == E::value) {
      element_done();
    }
    return true;
  }

 private:
  static constexpr std::size_t kSmall = 16;
  struct Open {
    bool object;
    std::vector<std::string> fields;       // in order (the path names the last)
    std::unordered_set<std::string> wide;  // the same, once there are kSmall of them
    std::size_t elements;
  };
  void element_done() {
    if (!open_.empty() && !open_.back().object) ++open_.back().elements;
  }
  // The innermost open object's path: each enclosing container's current member.
  std::string path() const {
    std::string w;
    for (std::size_t k = 0; k + 1 < open_.size(); ++k) {
      if (!open_[k].object) {
        w.append("[").append(std::to_string(open_[k].elements)).append("]");
        continue;
      }
      if (!w.empty()) w.append(".");
      w.append(open_[k].fields.back());
    }
    return w;
  }
  std::vector<Open> open_;
};

}  // namespace detail

// nlohmann::json::parse(input), refusing a repeated field (DuplicateField); its other
// errors as nlohmann throws them.
template <class Input>
nlohmann::json parse_unique_fields(Input&& input) {
  return nlohmann::json::parse(std::forward<Input>(input), detail::UniqueFields{});
}

}  // namespace dtlab
