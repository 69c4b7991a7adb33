#pragma once
// The machinery of the record's description (record_fields.h). A field of a recorded object of
// type T is its key, its documentation, an accessor into T and a codec (record_codecs.h); from
// those come how the field is written into the step's JSON line and read back from it. An
// object's fields are its Table; RecordSchema holds one table per kind of object of a step, and
// the writer (record_line.h), the reader (record_step_reader.h) and the documentation walk them.
#include <algorithm>
#include <cstring>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "sim/json_line.h"
#include "sim/step_record.h"
#include "spec/json_text.h"

namespace canopy::sim {

struct RecordSchema;
struct RecordField;

/// Where a value sits in a line: "uavs.0.p" is {{{root, "uavs"}, 0}, "p"}; rendered only when an
/// error names it.
struct At {
  const At* parent = nullptr;
  const char* key = nullptr;  // a member's key, or
  long index = -1;            // a list element's index
  std::string text() const {
    std::string out = parent ? parent->text() : "";
    if (key == nullptr && index < 0) return out;
    if (!out.empty()) out += '.';
    return out + (key ? std::string(key) : std::to_string(index));
  }
};

/// What a line is written with: the JSON text, the schema, and the scenario's labels (escaped
/// once, when first written, so a label JSON cannot hold fails the step that first writes it).
class LineOut {
 public:
  LineOut(JsonLine& json, const RecordSchema& tables, const std::vector<std::string>& names,
          std::vector<std::optional<std::string>>& escaped)
      : j(json), schema(tables), names_(names), escaped_(escaped) {}
  const std::string& label(sensing::LabelId id) {
    std::optional<std::string>& e = escaped_.at(static_cast<std::size_t>(id));
    if (!e) e = JsonLine::escaped(names_.at(static_cast<std::size_t>(id)));
    return *e;
  }
  JsonLine& j;
  const RecordSchema& schema;

 private:
  const std::vector<std::string>& names_;
  std::vector<std::optional<std::string>>& escaped_;
};

/// What a line is read against: the schema, the scenario's labels and the sizes its lists must
/// have (one entry per UAV, per target). Every fault is a ScenarioError naming the file, the
/// line and the field (fail()).
struct LineIn {
  const RecordSchema& schema;
  const std::string& file;
  int line = 0;
  const std::vector<std::string>& labels;
  std::size_t uavs = 0, targets = 0;
  [[noreturn]] void fail(const At& at, const std::string& expected) const;
};

/// The packing of a field the compact record has no coding of its own for (a field added to the
/// tables): its JSON text, length-prefixed, in the structure column (record_extras.h).
inline constexpr const char* kGenericPacking = "structure: its JSON text";

template <typename T>
struct Field {
  const char* key;
  const char* type;     // JSON: integer, number, string, list, object, [number × 3], …
  const char* unit;     // SI; empty for counts, indices and labels
  const char* packing;  // the compact record's column and coding (step_columns.h)
  const char* meaning;
  void (*write)(LineOut&, const T&);
  void (*read)(const LineIn&, const spec::Json&, T&, const At&);
  /// Documentation rows of the object(s) it holds, under `prefix` (nullptr: a plain value).
  void (*children)(const RecordSchema&, const std::string& prefix,
                   std::vector<RecordField>&) = nullptr;
  bool (*present)(const T&) = nullptr;  // written only when true; nullptr: always written
  void (*found)(T&) = nullptr;          // read: the key was there (sets what present() tests)
  void (*reset)(T&) = nullptr;          // sets the value to its type's default
  bool per_agent = false;               // a list with one entry per agent (`--agent I` cuts it)

  /// The field written only when `is(t)`, optional when read (`mark(t)` once read).
  Field when(bool (*is)(const T&), void (*mark)(T&) = nullptr) const {
    Field f = *this;
    f.present = is;
    f.found = mark;
    return f;
  }
  /// The field a list of one entry per agent (record_slice.h keeps entry I of it).
  Field perAgent() const {
    Field f = *this;
    f.per_agent = true;
    return f;
  }
};

/// A field `key` of T: the value `get(t)` (a captureless lambda returning a reference into t),
/// written and read by `Codec` (record_codecs.h), which also names its JSON type.
template <typename T, typename Get, typename Codec>
Field<T> field(const char* key, Get, Codec, const char* unit, const char* packing,
               const char* meaning) {
  Field<T> f{key,
             Codec::kType,
             unit,
             packing,
             meaning,
             [](LineOut& out, const T& t) { Codec::write(out, Get{}(t)); },
             [](const LineIn& in, const spec::Json& v, T& t, const At& at) {
               Codec::read(in, v, Get{}(t), at);
             }};
  f.reset = [](T& t) {
    static const T kDefault{};
    Get{}(t) = Get{}(kDefault);
  };
  if constexpr (requires { &Codec::children; }) f.children = &Codec::children;
  return f;
}

/// An object's fields in the order they are read and documented; written in the order of their
/// keys' bytes (the order nlohmann's dump() gives, which the lines have always had).
template <typename T>
class Table {
 public:
  Table(std::initializer_list<Field<T>> fields) {
    for (const Field<T>& f : fields) add(f);
  }
  void add(const Field<T>& f) {
    if (std::strcmp(f.packing, kGenericPacking) == 0) generic_.push_back(fields_.size());
    fields_.push_back(f);
    by_key_.push_back(fields_.size() - 1);
    std::sort(by_key_.begin(), by_key_.end(), [this](std::size_t a, std::size_t b) {
      return std::strcmp(fields_[a].key, fields_[b].key) < 0;
    });
  }
  const std::vector<Field<T>>& fields() const { return fields_; }
  const std::vector<std::size_t>& byKey() const { return by_key_; }
  /// The fields with kGenericPacking, in table order.
  const std::vector<std::size_t>& generic() const { return generic_; }

 private:
  std::vector<Field<T>> fields_;
  std::vector<std::size_t> by_key_, generic_;
};

template <typename T>
void writeObject(LineOut& out, const Table<T>& table, const T& t) {
  out.j.beginObject();
  for (const std::size_t i : table.byKey()) {
    const Field<T>& f = table.fields()[i];
    if (f.present && !f.present(t)) continue;
    out.j.key(f.key);
    f.write(out, t);
  }
  out.j.endObject();
}

template <typename T>
void readObject(const LineIn& in, const spec::Json& json, const Table<T>& table, T& t,
                const At& at) {
  if (!json.is_object()) in.fail(at, "an object");
  for (const Field<T>& f : table.fields()) {
    const At here{&at, f.key};
    const auto it = json.find(f.key);
    if (it == json.end()) {
      if (f.present) continue;  // an optional field
      in.fail(here, std::string("a field '") + f.key + "'");
    }
    f.read(in, *it, t, here);
    if (f.found) f.found(t);
  }
}

}  // namespace canopy::sim
