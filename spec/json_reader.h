#pragma once
// A JSON walker that knows where it is: every read names the file and the field path in its
// errors, records what it read (or the default it used) into the effective configuration, and
// finish() rejects fields nobody read. The loader reads scenarios with it, experiments/ sweep
// files and trial results.
#include <filesystem>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/enum_names.h"
#include "core/types.h"
#include "spec/error.h"
#include "spec/field_log.h"
#include "spec/json_text.h"

namespace canopy::spec {

/// Constraint on a number, checked after the type.
enum class Bound { any, positive, non_negative, probability, open_probability, unit_interval };

class ObjectReader;

/// What every field of one load shares: where the files a scenario names (includes, track CSVs)
/// may be read from, as canonical folders (the scenario's own folder, the scenario library, and
/// any the user allowed), and the factor on the work limits of spec/budget.h.
struct LoadContext {
  std::vector<std::filesystem::path> roots;
  double budget_scale = 1.0;
  FieldLog* log = nullptr;  // records every read (spec/field_log.h) when set
  /// When set, one pass finds every independent error: a field that fails a typed read
  /// (ObjectReader::number, …) is recorded here and its default used in its place, and
  /// finish() records every unknown field. Without it the first error is thrown.
  std::vector<ScenarioError>* errors = nullptr;
};

/// A value at a known place: its file, its field path, and the slot of the effective config it
/// fills.
class Field {
 public:
  Field(const Json& value, std::string file, std::string path, Json* out,
        const LoadContext* context = nullptr)
      : value_(&value),
        file_(std::move(file)),
        path_(std::move(path)),
        out_(out),
        context_(context) {}

  const Json& json() const { return *value_; }
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  Json* out() const { return out_; }  // this value's slot in the effective config (may be null)
  const LoadContext* context() const { return context_; }  // null: no file may be read through it
  [[noreturn]] void fail(const std::string& message) const;
  /// Records this field's type and range in the context's log (no-op without one).
  void note(const std::string& type, const std::string& range,
            const std::vector<std::string>& choices = {}) const;

  double number(Bound bound = Bound::any) const;
  int integer(int min_value, int max_value) const;
  std::uint64_t unsignedInteger() const;
  bool boolean() const;
  std::string string() const;
  /// One of `choices`; returns its index.
  int choice(const std::vector<std::string>& choices) const;
  Vec2 vec2(Bound bound = Bound::any) const;
  /// A JSON array: its elements as Fields (the effective config gets an array of the same size).
  std::vector<Field> elements(std::size_t min_size = 0, std::size_t max_size = SIZE_MAX) const;
  ObjectReader object() const;
  /// Copies the value unchanged into the effective config.
  void keepAsIs() const;

 private:
  const Json* value_;
  std::string file_;
  std::string path_;
  Json* out_;
  const LoadContext* context_;
};

/// Reads the members of one JSON object.
class ObjectReader {
 public:
  ObjectReader(const Field& field);
  const Field& field() const { return field_; }
  bool has(const std::string& key) const;
  /// A member that must be present.
  Field required(const std::string& key);
  /// A member that may be absent.
  std::optional<Field> optional(const std::string& key);

  double number(const std::string& key, double fallback, Bound bound = Bound::any);
  int integer(const std::string& key, int fallback, int min_value, int max_value);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key, const std::string& fallback);
  int choice(const std::string& key, const std::vector<std::string>& choices, int fallback);
  /// One of the spellings in `names` (core/enum_names.h); when absent, `fallback` — the config
  /// struct's default — recorded by its spelling.
  template <class Enum, std::size_t N>
  Enum enumeration(const std::string& key, const EnumNames<Enum, N>& names, Enum fallback) {
    std::vector<std::string> spellings;
    int fallback_index = -1;
    for (const EnumName<Enum>& entry : names) {
      if (entry.value == fallback) fallback_index = static_cast<int>(spellings.size());
      spellings.emplace_back(entry.name);
    }
    if (fallback_index < 0) throw std::logic_error("enumeration: the default has no spelling");
    return names[static_cast<std::size_t>(choice(key, spellings, fallback_index))].value;
  }
  /// Fails when two of the keys are present; returns the one present, or "" when none (after
  /// rejecting any unknown member, which is likely a misspelt alternative).
  std::string oneOf(const std::vector<std::string>& keys);
  /// Rejects every member not read. Call once, after all reads.
  void finish() const;
  /// Runs read(), a read of several fields; when the context collects errors and it fails, the
  /// error is recorded and false returned (the caller goes on with its defaults). Without a
  /// collecting context the error is thrown.
  template <class Read>
  bool attempt(Read read) {
    return orFallback(false, [&] {
      read();
      return true;
    });
  }

 private:
  /// Records a default in the effective config for a member that was absent, and in the log.
  void recordDefault(const std::string& key, const Json& value, const std::string& type,
                     const std::string& range, const std::vector<std::string>& choices = {});
  /// Logs that `key` may be absent with `value` as its default.
  void logDefault(const std::string& key, const Json& value);
  /// read(), or — when the context collects errors and read() fails — the error recorded and
  /// `fallback` returned, so that the fields after this one are still read.
  template <class T, class Read>
  T orFallback(const T& fallback, Read read) {
    if (!field_.context() || !field_.context()->errors) return read();
    try {
      return read();
    } catch (const ScenarioErrors& e) {
      field_.context()->errors->insert(field_.context()->errors->end(), e.errors().begin(),
                                       e.errors().end());
    } catch (const ScenarioError& e) {
      field_.context()->errors->push_back(e);
    }
    return fallback;
  }

  Field field_;
  std::set<std::string> read_;
};

}  // namespace canopy::spec
