#pragma once
// JSON text read within limits: every JSON file canopy reads (scenarios, layouts, sweeps, trial
// results) is parsed here, bounded in size and depth, with duplicate keys refused, and its syntax
// errors named by file, line and column.
#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

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

/// The most elements one array of a document may hold, checked while the text is parsed (before
/// the rest of the document is built): the array that is the value of top-level key `key` (or,
/// with key "", the document itself when it is an array). Refusing 10⁶ targets after building
/// all of them took 4.6 s; this stops at the first element past the limit.
struct ArrayLimit {
  std::string key;
  std::size_t max_elements = 0;
  /// The message when the array is longer, e.g. budgetMessage's; the error names the field.
  std::string message;
};

/// Thrown by parseBoundedJson for an array longer than its ArrayLimit.
struct JsonArrayTooLong : std::length_error {
  explicit JsonArrayTooLong(const ArrayLimit& l)
      : std::length_error("JSON array too long"), limit(l) {}
  ArrayLimit limit;
};

/// The JSON library's parse (comments allowed), refusing nesting deeper than kMaxJsonDepth before
/// it is built (printing and destroying a value recurse on its depth): JsonTooDeep; a key twice
/// in one object: JsonDuplicateKey; an array longer than its limit in `limits`:
/// JsonArrayTooLong; the library's own exceptions for anything else.
Json parseBoundedJson(const std::string& text, const std::vector<ArrayLimit>& limits = {});

/// Parses JSON with comments, nested at most kMaxJsonDepth deep; syntax errors become ScenarioError
/// naming file:line:column; an array past its limit, a ScenarioError naming file and key.
Json parseJson(const std::string& text, const std::string& file,
               const std::vector<ArrayLimit>& limits = {});
/// The text of a regular file of at most kMaxJsonBytes (never through a link, never from a FIFO);
/// anything else is a ScenarioError naming `referenced_from` (or the path).
std::string readJsonText(const std::string& path, const std::string& referenced_from = "");
/// Reads and parses a regular file of at most kMaxJsonBytes; anything else is a ScenarioError.
Json readJsonFile(const std::string& path, const std::string& referenced_from = "");

/// Largest result file read back whole (record.jsonl, read line by line, may be this long): 1 GiB.
constexpr std::size_t kMaxResultBytes = std::size_t{1} << 30;

/// The text of a file canopy reads back (a run's manifest, record or summary, a sweep's files,
/// trial results, a golden CSV): a regular file of at most `max_bytes`, read without waiting (a
/// FIFO or device is refused, not opened for reading). A directory, FIFO, device, symbolic link
/// (or link loop), missing or oversized file is a ScenarioError naming the file and saying it
/// should be `what` ("the manifest that `canopy run` writes"). With `follow_links` (a path the
/// user typed) one chain of links is followed first; a loop is still refused.
std::string readResultText(const std::filesystem::path& path, const std::string& what,
                           std::size_t max_bytes = kMaxJsonBytes, bool follow_links = false);
/// readResultText, then the bounded parse (depth, duplicate keys), errors naming the file.
Json readResultJson(const std::filesystem::path& path, const std::string& what);

/// "a string \"x\"", "the number -3", "an array", ... for messages.
std::string describe(const Json& value);

}  // namespace canopy::spec
