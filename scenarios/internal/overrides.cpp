// --set dotted.path=value: edits the raw document before it is validated.
#include <algorithm>
#include <cctype>

#include "core/printable.h"
#include "scenarios/internal/sections.h"

namespace canopy::scenarios::internal {

void applyOverride(Json& document, const std::string& assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw ScenarioError("--set", assignment, "expected key=value, e.g. planner.horizon=1");
  }
  const std::string key = assignment.substr(0, equals);
  const std::string text = assignment.substr(equals + 1);
  Json value;
  try {
    value = parseBoundedJson(text);  // numbers, booleans, null, arrays, objects, "quoted strings"
  } catch (const JsonTooDeep&) {
    throw ScenarioError("--set", key,
                        "expected a value nested at most " + std::to_string(kMaxJsonDepth) +
                            " levels deep (arrays and objects)");
  } catch (const JsonDuplicateKey& e) {
    throw ScenarioError("--set", key,
                        "the key \"" + printable(e.key, 60) + "\" appears twice in one object");
  } catch (const Json::parse_error&) {
    value = text;  // a bare word: a string (e.g. planner.algorithm=sma)
  } catch (const Json::exception& e) {
    throw ScenarioError("--set", assignment, "expected a finite value: " + std::string(e.what()));
  }

  Json* node = &document;
  std::string walked;
  std::size_t start = 0;
  while (true) {
    const auto dot = key.find('.', start);
    const std::string part =
        key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (part.empty())
      throw ScenarioError("--set", key, "expected a dotted path without empty parts");
    const bool is_index = std::all_of(part.begin(), part.end(), [](char c) {
      return std::isdigit(static_cast<unsigned char>(c));
    });
    Json* next = nullptr;
    if (node->is_array()) {
      if (!is_index || std::stoull(part) >= node->size()) {
        throw ScenarioError("--set", key,
                            "'" + walked + "' is an array of " + std::to_string(node->size()) +
                                " elements; expected an index below that, got '" + part + "'");
      }
      next = &(*node)[std::stoull(part)];
    } else if (node->is_object() || node->is_null()) {
      if (node->is_null()) *node = Json::object();
      next = &(*node)[part];
    } else {
      throw ScenarioError("--set", key,
                          "'" + walked + "' is " + describe(*node) + ", not an object or array");
    }
    walked += (walked.empty() ? "" : ".") + part;
    node = next;
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  *node = value;
}

}  // namespace canopy::scenarios::internal
