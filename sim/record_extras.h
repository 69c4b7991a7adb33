#pragma once
// The compact record's coding of the fields that have no packing of their own (kGenericPacking,
// record_schema.h): a field added to the record's tables is carried by the compact record
// (step_columns.h) this way, byte-identical when decoded, until it is given a packing. After an
// object's own values, per such field in table order: 0 when the field is not written for the
// object, else the length of its JSON text + 1 and the text, in the structure column. Tables
// without such fields (the record's own) add no bytes.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "sim/column_bytes.h"
#include "sim/record_fields.h"
#include "spec/result_lines.h"

namespace canopy::sim {

class RecordExtras {
 public:
  RecordExtras(const RecordSchema& schema, const std::vector<std::string>& labels)
      : schema_(schema), labels_(labels), escaped_(labels.size()) {}

  const RecordSchema& schema() const { return schema_; }

  /// The bytes of t's generic fields (empty for a table without any).
  template <typename T>
  std::string text(const Table<T>& table, const T& t) {
    ColumnOut c;
    for (const std::size_t i : table.generic()) {
      const Field<T>& f = table.fields()[i];
      if (f.present && !f.present(t)) {
        c.u(0);
        continue;
      }
      std::string json;
      JsonLine j(json);
      LineOut out(j, schema_, labels_, escaped_);
      f.write(out, t);
      c.u(json.size() + 1);
      c.bytes() += json;
    }
    return std::move(c.bytes());
  }
  template <typename T>
  void encode(const Table<T>& table, const T& t, ColumnOut& s) {
    if (!table.generic().empty()) s.bytes() += text(table, t);
  }
  /// Reads t's generic fields; uavs, targets: the step's counts (what a list of one entry per UAV
  /// or target must hold).
  template <typename T>
  void decode(const Table<T>& table, T& t, ColumnIn& s, std::size_t uavs, std::size_t targets) {
    for (const std::size_t i : table.generic()) {
      const Field<T>& f = table.fields()[i];
      const std::uint64_t n = s.u();
      f.reset(t);
      if (n == 0) continue;
      const std::optional<spec::Json> json = spec::parseResultLine(std::string(s.raw(n - 1)));
      if (!json) s.fail(std::string("the JSON text of '") + f.key + "'");
      const LineIn in{schema_, kWhere, 0, labels_, uavs, targets};
      f.read(in, *json, t, At{nullptr, f.key});
      if (f.found) f.found(t);
    }
  }

 private:
  inline static const std::string kWhere = "the compact record";
  const RecordSchema& schema_;
  std::vector<std::string> labels_;
  std::vector<std::optional<std::string>> escaped_;
};

}  // namespace canopy::sim
