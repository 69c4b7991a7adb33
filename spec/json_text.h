#pragma once
// JSON text read within limits: every JSON file canopy reads (scenarios, layouts, sweeps, trial
// results) is parsed here, bounded in size and depth, with duplicate keys refused, and its syntax
// errors named by file, line and column.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "spec/error.h"

namespace canopy::spec {

// std::map-backed: slots of the effective config keep their address while siblings are added.
using Json = nlohmann::json;

constexpr int kMaxJsonDepth = 64;                             // nested arrays and objects
constexpr std::size_t kMaxJsonBytes = std::size_t{64} << 20;  // 64 MiB

/// Thrown by parseBoundedJson for input nested deeper than kMaxJsonDepth.
struct JsonTooDeep : std::length_error {
  JsonTooDeep() : std::length_error("JSON nested too deep") {}
};

/// Thrown by parseBoundedJson for an object that gives a key twice.
struct JsonDuplicateKey : std::invalid_argument {
  explicit JsonDuplicateKey(std::string k)
      : std::invalid_argument("duplicate JSON key"), key(std::move(k)) {}
  std::string key;
};

/// The JSON library's parse (comments allowed), refusing nesting deeper than kMaxJsonDepth before
/// it is built (printing and destroying a value recurse on its depth): JsonTooDeep; a key twice
/// in one object: JsonDuplicateKey; the library's own exceptions for anything else.
Json parseBoundedJson(const std::string& text);

/// Parses JSON with comments, nested at most kMaxJsonDepth deep; syntax errors become ScenarioError
/// naming file:line:column.
Json parseJson(const std::string& text, const std::string& file);
/// The text of a regular file of at most kMaxJsonBytes (never through a link, never from a FIFO);
/// anything else is a ScenarioError naming `referenced_from` (or the path).
std::string readJsonText(const std::string& path, const std::string& referenced_from = "");
/// Reads and parses a regular file of at most kMaxJsonBytes; anything else is a ScenarioError.
Json readJsonFile(const std::string& path, const std::string& referenced_from = "");

/// "a string \"x\"", "the number -3", "an array", ... for messages.
std::string describe(const Json& value);

}  // namespace canopy::spec
