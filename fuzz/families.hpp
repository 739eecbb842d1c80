#pragma once
// The registry of point-set families: `dtlab fuzz --family NAME`.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "predicates/point.hpp"

namespace dtlab::fuzz {

struct Family {
  std::string name;
  std::string description;  // one line: the degeneracy it targets
  // Exactly n points; the same (n, seed) gives the same bits on every platform.
  std::function<std::vector<Point3>(std::size_t n, std::uint64_t seed)> generate;
};

const std::vector<Family>& families();

// The family called `name`, or nullptr.
const Family* find_family(const std::string& name);

}  // namespace dtlab::fuzz
