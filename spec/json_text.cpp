#include "spec/json_text.h"

#include <cmath>
#include <filesystem>
#include <optional>
#include <set>
#include <vector>

#include "core/printable.h"
#include "core/text_file.h"

namespace canopy::spec {
namespace {

std::string shortDump(const Json& value) {
  // Depth is bounded at parse time (kMaxJsonDepth), so dump() recurses at most that deep.
  std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
  return text.size() > 40 ? printable(text, 37) : printable(text);
}

}  // namespace

Json parseBoundedJson(const std::string& text) {
  // The keys seen so far in each open object: a key given twice would silently keep the last.
  std::vector<std::set<std::string>> keys;
  const Json::parser_callback_t check = [&keys](int depth, Json::parse_event_t event,
                                                Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start:
      case Json::parse_event_t::array_start:
        if (depth > kMaxJsonDepth) throw JsonTooDeep();
        if (event == Json::parse_event_t::object_start) keys.emplace_back();
        break;
      case Json::parse_event_t::key:
        if (!keys.empty() && !keys.back().insert(parsed.get<std::string>()).second)
          throw JsonDuplicateKey(parsed.get<std::string>());
        break;
      case Json::parse_event_t::object_end:
        if (!keys.empty()) keys.pop_back();
        break;
      default:
        break;
    }
    return true;
  };
  return Json::parse(text, check, /*allow_exceptions=*/true, /*ignore_comments=*/true);
}

Json parseJson(const std::string& text, const std::string& file) {
  try {
    return parseBoundedJson(text);
  } catch (const Json::parse_error& e) {
    // e.what(): "[json.exception.parse_error.101] parse error at line L, column C: detail"
    std::string detail = e.what();
    std::string where;
    const auto at = detail.find(" at line ");
    const auto colon = detail.find(": ", at == std::string::npos ? 0 : at);
    if (at != std::string::npos && colon != std::string::npos) {
      where = detail.substr(at + 4, colon - at - 4);  // "line L, column C"
      detail = detail.substr(colon + 2);
    }
    throw ScenarioError(file, where, "invalid JSON: " + printable(detail, 200));
  } catch (const Json::exception& e) {
    // e.g. out_of_range.406 "number overflow parsing '1e999'": JSON has no infinities.
    std::string detail = e.what();
    const auto bracket = detail.find("] ");
    if (bracket != std::string::npos) detail = detail.substr(bracket + 2);
    throw ScenarioError(file, "",
                        "invalid JSON: " + printable(detail, 200) + " (numbers must be finite)");
  } catch (const JsonDuplicateKey& e) {
    throw ScenarioError(file, "",
                        "invalid JSON: the key \"" + printable(e.key, 60) +
                            "\" appears twice in one object (only one value can count)");
  } catch (const JsonTooDeep&) {
    throw ScenarioError(file, "",
                        "expected JSON nested at most " + std::to_string(kMaxJsonDepth) +
                            " levels deep (arrays and objects), this file nests deeper");
  }
}

std::string readJsonText(const std::string& path, const std::string& referenced_from) {
  std::string why;
  std::error_code error;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
  std::optional<std::string> text =
      error ? std::nullopt : readRegularFile(canonical, kMaxJsonBytes, why);
  if (!text) {
    throw ScenarioError(
        referenced_from.empty() ? printable(path, 200) : referenced_from, "",
        "cannot read file '" + printable(path, 200) + "'" + (why.empty() ? "" : ": " + why));
  }
  return std::move(*text);
}

Json readJsonFile(const std::string& path, const std::string& referenced_from) {
  return parseJson(readJsonText(path, referenced_from), path);
}

std::string describe(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return "the boolean " + value.dump();
    case Json::value_t::string:
      return "the string " + shortDump(value);
    case Json::value_t::array:
      return "an array " + shortDump(value);
    case Json::value_t::object:
      return "an object " + shortDump(value);
    case Json::value_t::number_float:
      if (!std::isfinite(value.get<double>())) return "a non-finite number";
      return "the number " + value.dump();
    default:
      return "the number " + value.dump();
  }
}

}  // namespace canopy::spec
