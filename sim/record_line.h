#pragma once
// One step of the record as its JSON line (record.jsonl): what `--record jsonl` writes and what
// the compact record's steps decode to (compact_record.h), written by the same code so the two
// are byte-identical. The line is the record's description (record_fields.h) written out: every
// field of its tables, keys in byte order.
#include <optional>
#include <string>
#include <vector>

#include "sim/json_line.h"
#include "sim/record_fields.h"
#include "sim/step_record.h"

namespace canopy::sim {

/// Labels as dump() escapes them, each escaped once, when it is first written (so a label that
/// dump() would refuse fails the run at the same step as before).
class RecordLineWriter {
 public:
  explicit RecordLineWriter(const std::vector<std::string>& labels,
                            const RecordSchema& schema = recordSchema())
      : schema_(schema), names_(labels), labels_(labels.size()) {}

  /// Appends the step's line (without the newline) to `out`.
  void write(const StepRecord& record, std::string& out);

 private:
  const RecordSchema& schema_;
  std::vector<std::string> names_;                  // the scenario's labels, by LabelId
  std::vector<std::optional<std::string>> labels_;  // escaped, once written
  DoubleTextCache numbers_;                         // the text of recent doubles
};

/// One step as a JSON line (without the newline); labels: the scenario's, by LabelId.
std::string recordLine(const std::vector<std::string>& labels, const StepRecord& record,
                       const RecordSchema& schema = recordSchema());

}  // namespace canopy::sim
