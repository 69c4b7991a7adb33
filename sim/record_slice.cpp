#include "sim/record_slice.h"

#include <algorithm>
#include <vector>

#include "sim/record_fields.h"

namespace canopy::sim {
namespace {

// Where the JSON value starting at `at` ends (one past its last byte), for the compact text the
// recorder writes (no spaces); npos when the text ends first.
std::size_t valueEnd(std::string_view text, std::size_t at) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = at; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        in_string = false;
        if (depth == 0) return i + 1;
      }
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if (c == ']' || c == '}') {
      if (--depth == 0) return i + 1;
      if (depth < 0) return i;
    } else if (depth == 0 && (c == ',')) {
      return i;
    }
  }
  return depth == 0 && !in_string ? text.size() : std::string_view::npos;
}

// The `index`th element of the array text [begin, end), or nothing.
std::optional<std::string_view> element(std::string_view array, std::size_t index) {
  std::size_t at = 1, n = 0;
  while (at < array.size() && array[at] != ']') {
    const std::size_t end = valueEnd(array, at);
    if (end == std::string_view::npos || end >= array.size()) return std::nullopt;
    if (n == index) return array.substr(at, end - at);
    ++n;
    at = end + (array[end] == ',' ? 1 : 0);
  }
  return std::nullopt;
}

// The quoted keys of the step's lists of one entry per agent (record_fields.h: "agents", "scans").
const std::vector<std::string>& perAgentKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> out;
    for (const Field<StepRecord>& f : recordSchema().step.fields()) {
      if (f.per_agent) out.push_back("\"" + std::string(f.key) + "\"");
    }
    return out;
  }();
  return keys;
}

}  // namespace

std::optional<std::string> agentSlice(std::string_view line, std::size_t agent) {
  if (line.empty() || line.front() != '{') return std::nullopt;
  const std::vector<std::string>& per_agent = perAgentKeys();
  std::string out = "{";
  std::size_t at = 1;
  int cut = 0;
  while (at < line.size() && line[at] != '}') {
    const std::size_t key_end = valueEnd(line, at);  // "key"
    if (line[at] != '"' || key_end == std::string_view::npos || key_end >= line.size() ||
        line[key_end] != ':')
      return std::nullopt;
    const std::string_view key = line.substr(at, key_end - at);
    const std::size_t value_at = key_end + 1;
    const std::size_t value_end = valueEnd(line, value_at);
    if (value_end == std::string_view::npos || value_end >= line.size()) return std::nullopt;
    std::string_view value = line.substr(value_at, value_end - value_at);
    if (out.size() > 1) out += ',';
    out.append(key);
    out += ':';
    const bool cut_here = std::find(per_agent.begin(), per_agent.end(), key) != per_agent.end();
    if (cut_here && value.front() == '[') {
      const std::optional<std::string_view> entry = element(value, agent);
      if (!entry) return std::nullopt;
      out += '[';
      out.append(*entry);
      out += ']';
      ++cut;
    } else {
      out.append(value);
    }
    at = value_end + (line[value_end] == ',' ? 1 : 0);
  }
  if (cut != static_cast<int>(per_agent.size())) return std::nullopt;
  out += '}';
  return out;
}

}  // namespace canopy::sim
