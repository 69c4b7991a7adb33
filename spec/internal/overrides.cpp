// --set dotted.path=value: edits the raw document before it is validated.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <optional>

#include "core/printable.h"
#include "spec/internal/sections.h"

namespace canopy::spec::internal {
namespace {

// Messages quote at most this many bytes of an override (a command-line argument can be 128 KiB).
constexpr std::size_t kQuoted = 200;

// The value of an override: JSON (numbers, booleans, null, arrays, objects, "quoted strings")
// nested at most kMaxJsonDepth deep, or else the text itself as a string (a bare word, e.g.
// planner.algorithm=sma).
Json overrideValue(const std::string& text, const std::string& shown) {
  try {
    return parseBoundedJson(text);
  } catch (const JsonTooDeep&) {
    throw ScenarioError("--set", shown,
                        "expected a value nested at most " + std::to_string(kMaxJsonDepth) +
                            " levels deep (arrays and objects)");
  } catch (const JsonDuplicateKey& e) {
    throw ScenarioError("--set", shown,
                        "the key \"" + printable(e.key, 60) + "\" appears twice in one object");
  } catch (const Json::parse_error&) {
    return text;
  } catch (const Json::exception&) {  // out_of_range.406: a number beyond double, e.g. 1e999
    throw ScenarioError("--set", shown,
                        "expected a finite value, got '" + printable(text, kQuoted) + "'");
  }
}

// `part` as an array index, or nothing when it is not a decimal integer that fits.
std::optional<std::size_t> indexOf(const std::string& part) {
  const bool digits = std::all_of(
      part.begin(), part.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
  std::size_t index = 0;
  const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), index);
  if (!digits || error != std::errc() || end != part.data() + part.size()) return std::nullopt;
  return index;
}

}  // namespace

void applyOverride(Json& document, const std::string& assignment) {
  const std::string shown = printable(assignment, kQuoted);
  if (!isValidUtf8(assignment)) {
    throw ScenarioError("--set", shown, "expected UTF-8 text, got bytes that are not");
  }
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw ScenarioError("--set", shown, "expected key=value, e.g. planner.horizon=1");
  }
  const std::string key = assignment.substr(0, equals);
  const std::string shown_key = printable(key, kQuoted);
  const Json value = overrideValue(assignment.substr(equals + 1), shown_key);

  Json* node = &document;
  std::string walked;
  std::size_t start = 0;
  while (true) {
    const auto dot = key.find('.', start);
    const std::string part =
        key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (part.empty())
      throw ScenarioError("--set", shown_key, "expected a dotted path without empty parts");
    Json* next = nullptr;
    if (node->is_array()) {
      const std::optional<std::size_t> index = indexOf(part);
      if (!index || *index >= node->size()) {
        throw ScenarioError(
            "--set", shown_key,
            "'" + printable(walked) + "' is an array of " + std::to_string(node->size()) +
                " elements; expected an index below that, got '" + printable(part, 40) + "'");
      }
      next = &(*node)[*index];
    } else if (node->is_object() || node->is_null()) {
      if (node->is_null()) *node = Json::object();
      next = &(*node)[part];
    } else {
      throw ScenarioError(
          "--set", shown_key,
          "'" + printable(walked) + "' is " + describe(*node) + ", not an object or array");
    }
    walked += (walked.empty() ? "" : ".") + part;
    node = next;
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  *node = value;
}

}  // namespace canopy::spec::internal
