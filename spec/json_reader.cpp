#include "spec/json_reader.h"

#include <cmath>
#include <limits>
#include <optional>

#include "core/nearest_word.h"
#include "core/printable.h"
#include "core/progress.h"
#include "core/text_file.h"
#include "spec/internal/referenced_file.h"

namespace canopy::spec {
namespace {

// Arrays at least this long report the listing of their elements (Field::elements).
constexpr std::size_t kListedWithProgress = 65536;

std::string joinPath(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

// How an error names what a bound accepts, and how the schema writes its range.
struct BoundWords {
  const char* accepted;
  const char* range;
};

BoundWords boundWords(Bound bound) {
  switch (bound) {
    case Bound::any:
      return {"a finite number", ""};
    case Bound::positive:
      return {"a positive number", "> 0"};
    case Bound::non_negative:
      return {"a number >= 0", ">= 0"};
    case Bound::probability:
      return {"a probability in [0, 1]", "[0, 1]"};
    case Bound::open_probability:
      return {"a probability in (0, 1)", "(0, 1)"};
    case Bound::unit_interval:
      return {"a number in (0, 1]", "(0, 1]"};
  }
  return {"a number", ""};
}

const char* boundText(Bound bound) {
  return boundWords(bound).accepted;
}
const char* rangeText(Bound bound) {
  return boundWords(bound).range;
}

std::string intRange(int min_value, int max_value) {
  return "[" + std::to_string(min_value) + ", " + std::to_string(max_value) + "]";
}

bool satisfies(double x, Bound bound) {
  switch (bound) {
    case Bound::any:
      return true;
    case Bound::positive:
      return x > 0.0;
    case Bound::non_negative:
      return x >= 0.0;
    case Bound::probability:
      return x >= 0.0 && x <= 1.0;
    case Bound::open_probability:
      return x > 0.0 && x < 1.0;
    case Bound::unit_interval:
      return x > 0.0 && x <= 1.0;
  }
  return false;
}

// The log's record of the object at `object_path` of `file` (null without a log).
ObjectShape* shapeOf(const LoadContext* context, const std::string& file,
                     const std::string& object_path) {
  if (!context || !context->log) return nullptr;
  FieldInfo& info = (*context->log)[fieldPattern(object_path)];
  info.path = fieldPattern(object_path);
  return &info.instances[file + "#" + object_path];
}

// Records that the member at `path` (an object's member, not a list's element) had the choice
// `value`, in its object's shape.
void noteChoice(const LoadContext* context, const std::string& file, const std::string& path,
                const std::string& value) {
  if (path.empty() || path.back() == ']') return;
  const std::size_t dot = path.rfind('.');
  const std::string parent = dot == std::string::npos ? "" : path.substr(0, dot);
  const std::string key = dot == std::string::npos ? path : path.substr(dot + 1);
  if (ObjectShape* shape = shapeOf(context, file, parent)) shape->choices[key] = value;
}

}  // namespace

void Field::fail(const std::string& message) const {
  throw ScenarioError(file_, path_, message);
}

void Field::note(const std::string& type, const std::string& range,
                 const std::vector<std::string>& choices) const {
  if (!context_ || !context_->log) return;
  FieldInfo& info = (*context_->log)[fieldPattern(path_)];
  info.path = fieldPattern(path_);
  // Read with a bound in one place and none in another (the rows [t, x, y] of a track): no one
  // range.
  if (info.type == type && info.range != range) info.range_varies = true;
  // A field that takes several forms (a radius or a [min, max] range) lists each: "number | array".
  if (info.type.empty()) {
    info.type = type;
  } else if (("| " + info.type + " |").find("| " + type + " |") == std::string::npos) {
    info.type += " | " + type;
  }
  if (!range.empty() && !info.range.empty() && info.range != range) info.range_varies = true;
  if (!range.empty()) info.range = range;
  if (!choices.empty()) info.choices = choices;
}

double Field::number(Bound bound) const {
  note("number", rangeText(bound));
  if (!value_->is_number())
    fail(std::string("expected ") + boundText(bound) + ", got " + describe(*value_));
  const double x = value_->get<double>();
  if (!std::isfinite(x))
    fail(std::string("expected ") + boundText(bound) + ", got " + describe(*value_));
  if (!satisfies(x, bound))
    fail(std::string("expected ") + boundText(bound) + ", got " + describe(*value_));
  if (out_) *out_ = x;
  return x;
}

int Field::integer(int min_value, int max_value) const {
  note("integer", intRange(min_value, max_value));
  const std::string expected =
      "an integer in [" + std::to_string(min_value) + ", " + std::to_string(max_value) + "]";
  if (!value_->is_number_integer()) fail("expected " + expected + ", got " + describe(*value_));
  const auto x = value_->get<long long>();
  if (value_->is_number_unsigned() &&
      value_->get<unsigned long long>() > static_cast<unsigned long long>(max_value)) {
    fail("expected " + expected + ", got " + describe(*value_));
  }
  if (x < min_value || x > max_value) fail("expected " + expected + ", got " + describe(*value_));
  if (out_) *out_ = x;
  return static_cast<int>(x);
}

std::uint64_t Field::unsignedInteger() const {
  note("integer", ">= 0");
  if (!value_->is_number_unsigned()) {
    fail("expected a non-negative integer, got " + describe(*value_));
  }
  const auto x = value_->get<std::uint64_t>();
  if (out_) *out_ = x;
  return x;
}

bool Field::boolean() const {
  note("boolean", "");
  if (!value_->is_boolean()) fail("expected true or false, got " + describe(*value_));
  if (out_) *out_ = value_->get<bool>();
  return value_->get<bool>();
}

std::string Field::string() const {
  note("string", "");
  if (!value_->is_string()) fail("expected a string, got " + describe(*value_));
  if (out_) *out_ = *value_;
  return value_->get<std::string>();
}

int Field::choice(const std::vector<std::string>& choices) const {
  note("string", "", choices);
  std::string options;
  for (const std::string& c : choices) options += (options.empty() ? "\"" : ", \"") + c + "\"";
  if (value_->is_string()) {
    const std::string text = value_->get<std::string>();
    for (std::size_t i = 0; i < choices.size(); ++i) {
      if (choices[i] == text) {
        noteChoice(context_, file_, path_, text);
        if (out_) *out_ = text;
        return static_cast<int>(i);
      }
    }
  }
  const std::string guess =
      value_->is_string() ? nearestWord(value_->get<std::string>(), choices) : "";
  fail("expected one of " + options + ", got " + describe(*value_) +
       (guess.empty() ? "" : "; did you mean \"" + guess + "\"?"));
}

Vec2 Field::vec2(Bound bound) const {
  const std::vector<Field> xy = elements(2, 2);
  return {xy[0].number(bound), xy[1].number(bound)};
}

std::vector<Field> Field::elements(std::size_t min_size, std::size_t max_size) const {
  std::string expected = "an array";
  if (min_size == max_size) {
    expected = "an array of " + std::to_string(min_size) + " elements";
  } else if (max_size != SIZE_MAX) {
    expected =
        "an array of " + std::to_string(min_size) + " to " + std::to_string(max_size) + " elements";
  } else if (min_size > 0) {
    expected = "an array of at least " + std::to_string(min_size) + " element" +
               (min_size == 1 ? "" : "s");
  }
  note("array", min_size == 0 && max_size == SIZE_MAX
                    ? ""
                    : (max_size == SIZE_MAX   ? std::to_string(min_size) + "+ elements"
                       : min_size == max_size ? std::to_string(min_size) + " elements"
                                              : std::to_string(min_size) + " to " +
                                                    std::to_string(max_size) + " elements"));
  if (!value_->is_array()) fail("expected " + expected + ", got " + describe(*value_));
  const std::size_t n = value_->size();
  if (n < min_size || n > max_size) {
    fail("expected " + expected + ", got " + std::to_string(n) + " element" + (n == 1 ? "" : "s"));
  }
  if (out_) {
    *out_ = Json::array();
    out_->get_ref<Json::array_t&>().resize(n);  // fixed size: element slots keep their address
  }
  // Listing 10⁶ elements, each with its path, takes seconds: a stage of its own (core/progress.h).
  std::optional<ProgressCounter> progress;
  if (n >= kListedWithProgress)
    progress.emplace("listing a long array's elements", static_cast<double>(n), 65536);
  std::vector<Field> fields;
  fields.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    fields.emplace_back((*value_)[i], file_, path_ + "[" + std::to_string(i) + "]",
                        out_ ? &(*out_)[i] : nullptr, context_);
    if (progress) progress->add();
  }
  return fields;
}

ObjectReader Field::object() const {
  return ObjectReader(*this);
}

void Field::keepAsIs() const {
  if (out_) *out_ = *value_;
}

ObjectReader::ObjectReader(const Field& field) : field_(field) {
  field.note("object", "");
  if (!field.json().is_object()) field.fail("expected an object, got " + describe(field.json()));
  if (field_.out() && !field_.out()->is_object()) *field_.out() = Json::object();
  shapeOf(field_.context(), field_.file(), field_.path());
}

bool ObjectReader::has(const std::string& key) const {
  return field_.json().contains(key);
}

Field ObjectReader::required(const std::string& key) {
  if (auto f = optional(key)) {
    if (field_.context() && field_.context()->log) {
      FieldInfo& info = (*field_.context()->log)[fieldPattern(f->path())];
      info.path = fieldPattern(f->path());
      info.required = !info.default_json;
      if (ObjectShape* shape = shapeOf(field_.context(), field_.file(), field_.path()))
        shape->required.insert(key);
    }
    return *f;
  }
  throw ScenarioError(field_.file(), joinPath(field_.path(), key), "missing required field");
}

std::optional<Field> ObjectReader::optional(const std::string& key) {
  read_.insert(key);
  if (ObjectShape* shape = shapeOf(field_.context(), field_.file(), field_.path()))
    shape->allowed.insert(key);
  if (!has(key)) return std::nullopt;
  Json* slot = field_.out() ? &(*field_.out())[key] : nullptr;  // std::map: address is stable
  return Field(field_.json().at(key), field_.file(), joinPath(field_.path(), key), slot,
               field_.context());
}

void ObjectReader::logDefault(const std::string& key, const Json& value) {
  if (!field_.context() || !field_.context()->log) return;
  const std::string path = fieldPattern(joinPath(field_.path(), key));
  FieldInfo& info = (*field_.context()->log)[path];
  info.path = path;
  if (info.default_json && *info.default_json != value.dump()) info.default_varies = true;
  info.default_json = value.dump();
  info.required = false;
}

void ObjectReader::recordDefault(const std::string& key, const Json& value, const std::string& type,
                                 const std::string& range,
                                 const std::vector<std::string>& choices) {
  if (field_.out()) (*field_.out())[key] = value;
  logDefault(key, value);
  Field(value, field_.file(), joinPath(field_.path(), key), nullptr, field_.context())
      .note(type, range, choices);
}

double ObjectReader::number(const std::string& key, double fallback, Bound bound) {
  logDefault(key, fallback);
  if (auto f = optional(key)) return orFallback(fallback, [&] { return f->number(bound); });
  recordDefault(key, fallback, "number", rangeText(bound));
  return fallback;
}

int ObjectReader::integer(const std::string& key, int fallback, int min_value, int max_value) {
  logDefault(key, fallback);
  if (auto f = optional(key))
    return orFallback(fallback, [&] { return f->integer(min_value, max_value); });
  recordDefault(key, fallback, "integer", intRange(min_value, max_value));
  return fallback;
}

bool ObjectReader::boolean(const std::string& key, bool fallback) {
  logDefault(key, fallback);
  if (auto f = optional(key)) return orFallback(fallback, [&] { return f->boolean(); });
  recordDefault(key, fallback, "boolean", "");
  return fallback;
}

std::string ObjectReader::string(const std::string& key, const std::string& fallback) {
  logDefault(key, fallback);
  if (auto f = optional(key)) return orFallback(fallback, [&] { return f->string(); });
  recordDefault(key, fallback, "string", "");
  return fallback;
}

int ObjectReader::choice(const std::string& key, const std::vector<std::string>& choices,
                         int fallback) {
  logDefault(key, choices[fallback]);
  if (auto f = optional(key)) return orFallback(fallback, [&] { return f->choice(choices); });
  recordDefault(key, choices[fallback], "string", "", choices);
  noteChoice(field_.context(), field_.file(), joinPath(field_.path(), key), choices[fallback]);
  return fallback;
}

std::string ObjectReader::oneOf(const std::vector<std::string>& keys) {
  std::string found;
  for (const std::string& key : keys) {
    if (!has(key)) continue;
    if (!found.empty()) {
      field_.fail("give only one of \"" + found + "\" and \"" + key + "\"");
    }
    found = key;
  }
  read_.insert(keys.begin(), keys.end());  // all alternatives are known fields
  // None given: a misspelt alternative is the likeliest cause, so report stray fields first (and
  // only them: "give one of" after them would be their echo).
  if (found.empty()) {
    std::vector<ScenarioError>* errors = field_.context() ? field_.context()->errors : nullptr;
    const std::size_t before = errors ? errors->size() : 0;
    finish();
    if (errors && errors->size() > before) {
      std::vector<ScenarioError> stray(errors->begin() + static_cast<long>(before), errors->end());
      errors->erase(errors->begin() + static_cast<long>(before), errors->end());
      if (stray.size() == 1) throw stray[0];
      throw ScenarioErrors(std::move(stray));
    }
  }
  return found;
}

void ObjectReader::finish() const {
  for (const auto& [key, value] : field_.json().items()) {
    if (read_.count(key)) continue;
    std::string known;
    for (const std::string& k : read_) known += (known.empty() ? "" : ", ") + k;
    const std::string guess = nearestWord(key, {read_.begin(), read_.end()});
    ScenarioError unknown(field_.file(), joinPath(field_.path(), key),
                          "unknown field" +
                              (guess.empty() ? "" : "; did you mean \"" + guess + "\"?") +
                              " (expected one of: " + known + ")");
    if (!field_.context() || !field_.context()->errors) throw unknown;
    field_.context()->errors->push_back(std::move(unknown));  // and look for more
  }
}

std::string fieldPattern(const std::string& path) {
  std::string out;
  for (std::size_t i = 0; i < path.size(); ++i) {
    out += path[i];
    if (path[i] != '[') continue;
    while (i + 1 < path.size() && path[i + 1] >= '0' && path[i + 1] <= '9') ++i;
  }
  return out;
}

}  // namespace canopy::spec
