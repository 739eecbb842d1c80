#pragma once
// CaseRecord <-> one JSON line.
#include <nlohmann/json.hpp>

#include "fuzz/campaign.hpp"

namespace dtlab::fuzz {

nlohmann::json record_to_json(const CaseRecord& r);
CaseRecord record_from_json(const nlohmann::json& j);  // throws nlohmann::json::exception

}  // namespace dtlab::fuzz
