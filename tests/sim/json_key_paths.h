#pragma once
// Every key path of a JSON value ("a.b", "a.list[].c"): what the record and summary tests compare
// against the documentation and the writer's field table.
#include <nlohmann/json.hpp>
#include <set>
#include <string>

namespace canopy::sim::test {

inline void keysOf(const nlohmann::json& value, const std::string& path,
                   std::set<std::string>& out) {
  if (value.is_object()) {
    for (const auto& [key, child] : value.items()) {
      const std::string at = path.empty() ? key : path + "." + key;
      out.insert(at);
      keysOf(child, at, out);
    }
  } else if (value.is_array()) {
    for (const nlohmann::json& child : value) keysOf(child, path + "[]", out);
  }
}

}  // namespace canopy::sim::test
