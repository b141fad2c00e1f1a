#pragma once
// Test helper: a report without what measures the machine, to compare two runs of one bench.

#include <string>

#include <nlohmann/json.hpp>

namespace antipode::testing {

/// `value` without the entries that measure the machine (keys "seconds", "*_s", "*_s_*" and
/// "rss_mb"): what must be equal between two runs of one bench.
inline nlohmann::json without_seconds(const nlohmann::json& value) {
  if (value.is_array()) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& item : value) out.push_back(without_seconds(item));
    return out;
  }
  if (!value.is_object()) return value;
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [key, item] : value.items()) {
    const bool timing = key == "seconds" || key == "rss_mb" ||
                        key.find("_s_") != std::string::npos ||
                        (key.size() > 2 && key.compare(key.size() - 2, 2, "_s") == 0);
    if (!timing) out[key] = without_seconds(item);
  }
  return out;
}

}  // namespace antipode::testing
