#include "spec/json_text.h"

#include <cmath>
#include <filesystem>
#include <optional>
#include <set>
#include <vector>

#include "core/printable.h"
#include "core/progress.h"
#include "core/text_file.h"

namespace canopy::spec {
namespace {

std::string shortDump(const Json& value) {
  // Depth is bounded at parse time (kMaxJsonDepth), so dump() recurses at most that deep.
  std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
  return text.size() > 40 ? printable(text, 37) : printable(text);
}

// The library's DOM builder behind a SAX front that refuses depth and repeated keys as they
// arrive. Its callback parser did the same through a std::function per event and a keep/discard
// stack: 3.1 to 3.3 times the instructions for the whole validate of an array of 10⁴ to 4·10⁴
// UAV objects (bench/RESULTS.md); both are linear.
class BoundedSax {
 public:
  BoundedSax(Json& root, const std::vector<ArrayLimit>& limits)
      : dom_(root, /*allow_exceptions=*/true), limits_(limits) {}

  bool null() {
    element();
    return dom_.null();
  }
  bool boolean(bool value) {
    element();
    return dom_.boolean(value);
  }
  bool number_integer(Json::number_integer_t value) {
    element();
    return dom_.number_integer(value);
  }
  bool number_unsigned(Json::number_unsigned_t value) {
    element();
    return dom_.number_unsigned(value);
  }
  bool number_float(Json::number_float_t value, const Json::string_t& text) {
    element();
    return dom_.number_float(value, text);
  }
  bool string(Json::string_t& value) {
    element();
    return dom_.string(value);
  }
  bool binary(Json::binary_t& value) {
    element();
    return dom_.binary(value);
  }
  bool start_object(std::size_t size) {
    element();
    open(true);
    return dom_.start_object(size);
  }
  bool key(Json::string_t& key) {
    if (!keys_.back().insert(key).second) throw JsonDuplicateKey(key);
    if (objects_.size() == 1) top_key_ = key;  // a key of the document's own object
    return dom_.key(key);
  }
  bool end_object() {
    close();
    return dom_.end_object();
  }
  bool start_array(std::size_t size) {
    element();
    open(false);
    // The limited arrays: the document itself (key "") or the value of a top-level key.
    const bool root = objects_.size() == 1;
    const bool top_value = objects_.size() == 2 && objects_[0];
    if (root || top_value) {
      counted_ = nullptr;
      for (const ArrayLimit& limit : limits_) {
        if (root ? limit.key.empty() : !limit.key.empty() && limit.key == top_key_)
          counted_ = &limit;
      }
      counted_depth_ = objects_.size();
      count_ = 0;
    }
    return dom_.start_array(size);
  }
  bool end_array() {
    if (counted_ && objects_.size() == counted_depth_) counted_ = nullptr;
    close();
    return dom_.end_array();
  }
  template <class Exception>
  bool parse_error(std::size_t position, const std::string& token, const Exception& e) {
    return dom_.parse_error(position, token, e);
  }

 private:
  // A value starts: when its parent is the limited array, it is one more element. A large file
  // reports how far its reading got every 2^16 values.
  void element() {
    if ((++values_ & 0xffff) == 0)
      reportProgress("reading JSON (values)", static_cast<double>(values_), 0.0);
    if (counted_ && objects_.size() == counted_depth_ && ++count_ > counted_->max_elements)
      throw JsonArrayTooLong(*counted_);
  }

  // Nesting is refused before the container is built (printing and destroying a value recurse
  // on its depth): the containers already open, as the library's callback counts them.
  void open(bool object) {
    if (static_cast<int>(objects_.size()) > kMaxJsonDepth) throw JsonTooDeep();
    objects_.push_back(object);
    if (object) keys_.emplace_back();
  }
  void close() {
    if (objects_.back()) keys_.pop_back();
    objects_.pop_back();
  }

  nlohmann::detail::json_sax_dom_parser<Json> dom_;
  std::vector<bool> objects_;                // per open container: an object (else an array)
  std::vector<std::set<std::string>> keys_;  // per open object: the keys it gave
  const std::vector<ArrayLimit>& limits_;
  std::string top_key_;                  // the document's key whose value is being read
  const ArrayLimit* counted_ = nullptr;  // the limited array being read, if any
  std::size_t counted_depth_ = 0;         // the containers open while it takes elements
  std::size_t count_ = 0;                // its elements so far
  std::uint64_t values_ = 0;             // values read so far
};

}  // namespace

Json parseBoundedJson(const std::string& text, const std::vector<ArrayLimit>& limits) {
  Json root;
  BoundedSax sax(root, limits);
  Json::sax_parse(text, &sax, Json::input_format_t::json, /*strict=*/true,
                  /*ignore_comments=*/true);
  return root;
}

Json parseJson(const std::string& text, const std::string& file,
               const std::vector<ArrayLimit>& limits) {
  try {
    return parseBoundedJson(text, limits);
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
  } catch (const JsonArrayTooLong& e) {
    throw ScenarioError(file, e.limit.key, e.limit.message);
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

std::string readResultText(const std::filesystem::path& path, const std::string& what,
                           std::size_t max_bytes, bool follow_links) {
  namespace fs = std::filesystem;
  const std::string shown = printable(path.string(), 200);
  std::error_code error;
  const fs::file_status link = fs::symlink_status(path, error);
  if (!fs::exists(link)) throw ScenarioError(shown, "", "missing: expected " + what);
  fs::path target = path;
  if (fs::is_symlink(link)) {
    if (!follow_links)
      throw ScenarioError(shown, "", "is a symbolic link, expected " + what + " (a regular file)");
    target = fs::canonical(path, error);
    if (error) {
      throw ScenarioError(shown, "",
                          "is a symbolic link that leads nowhere (" + printable(error.message()) +
                              "), expected " + what);
    }
  }
  const fs::file_status status = fs::status(target, error);
  if (fs::is_directory(status))
    throw ScenarioError(shown, "", "is a directory, expected " + what + " (a regular file)");
  if (!error && !fs::is_regular_file(status)) {
    const char* kind = fs::is_fifo(status)                                          ? "a FIFO"
                       : fs::is_character_file(status) || fs::is_block_file(status) ? "a device"
                       : fs::is_socket(status)                                      ? "a socket"
                                                                                    : "not a file";
    throw ScenarioError(shown, "",
                        std::string("is ") + kind + ", expected " + what + " (a regular file)");
  }
  std::string why;
  std::optional<std::string> text = readRegularFile(target, max_bytes, why);
  if (!text) {
    throw ScenarioError(shown, "", "cannot be read as " + what + (why.empty() ? "" : ": " + why));
  }
  return std::move(*text);
}

Json readResultJson(const std::filesystem::path& path, const std::string& what) {
  return parseJson(readResultText(path, what), printable(path.string(), 200));
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
