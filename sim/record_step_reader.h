#pragma once
// The one reader of record lines: a line of record.jsonl (or of the compact record decoded) read
// into the step's structure (step_record.h) by the record's description (record_fields.h), each
// field checked as it is read. Every fault is a ScenarioError naming the file, the line and the
// field ("line 3: scans.0.in_footprint: expected target indices below 4"). The readers of run
// folders (record_reader.h, replay/run_folder.h, and through them `coverage`, `view`, the
// analysis and Python) read steps through here and take what they need from the structure.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "sim/record_fields.h"
#include "sim/record_lines.h"
#include "sim/step_record.h"
#include "spec/scenario_spec.h"

namespace canopy::sim {

/// What a record's lines are read against: the scenario's labels and how many UAVs and targets
/// each line lists.
struct RecordShape {
  std::vector<std::string> labels;
  std::size_t uavs = 0, targets = 0;
};
RecordShape shapeOf(const spec::ScenarioSpec& spec);

/// A ScenarioError "FILE: line N: FIELD: expected EXPECTED" (no field: "FILE: line N: expected …").
[[noreturn]] void failRecordLine(const std::string& file, int line, const std::string& field,
                                 const std::string& expected);

/// Line `number` of the record `file`, `text`, read into `step` (overwritten).
void readStepLine(const std::string& text, const std::string& file, int number,
                  const RecordShape& shape, StepRecord& step,
                  const RecordSchema& schema = recordSchema());

/// step_fn(step, number) for each line of the record at `path` (either form) within `range`.
void forEachRecordStep(const std::filesystem::path& path, const RecordShape& shape,
                       const LineRange& range,
                       const std::function<void(const StepRecord&, int)>& step_fn);

}  // namespace canopy::sim
