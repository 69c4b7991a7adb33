#pragma once
// The record of a run folder in either of its forms, read line by line: record.jsonl (plain JSON
// lines) or record.jsonl.zst (the same lines in zstd frames with a step index, compact_record.h).
// Every reader of records (sim/record_reader.h, replay/run_folder.h, `canopy record`, Python)
// reads through here, so a form is read the same way everywhere.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>

#include "spec/budget.h"
#include "spec/scenario_spec.h"

namespace canopy::sim {

/// How `canopy run` writes the record: plain JSON lines, the compact form, or (auto) the compact
/// form when the record is estimated at more than kCompactRecordAbove bytes (spec/budget.h's
/// record_bytes, an upper estimate) and plain lines below.
enum class RecordFormat { automatic, jsonl, compact };

inline constexpr const char* kRecordJsonlName = "record.jsonl";
inline constexpr const char* kRecordCompactName = "record.jsonl.zst";
inline constexpr double kCompactRecordAbove = spec::kCompactRecordAbove;

/// `format` with automatic resolved for `spec`.
RecordFormat resolveRecordFormat(RecordFormat format, const spec::ScenarioSpec& spec);

/// The record of the run folder `run_dir`: record.jsonl.zst when that name exists, else
/// record.jsonl (a run removes both before it writes one).
std::filesystem::path recordFileOf(const std::filesystem::path& run_dir);

/// Lines [first, end) of a record, counted from 0 over its non-blank lines: one line per
/// recorded step, so these are steps first..end−1 of a run.
struct LineRange {
  std::uint64_t first = 0;
  std::uint64_t end = std::numeric_limits<std::uint64_t>::max();
};

/// Calls line_fn(line, number) for each non-blank line of the record file `path` within `range`,
/// without its '\n'; `number` is its line number in the JSON lines text, from 1. The form is told
/// by the name (".zst": compact). The compact form decodes only the blocks that hold the range;
/// the plain form is read whole, bounded as a result file. Errors are ScenarioErrors naming the
/// file.
void forEachRecordLine(const std::filesystem::path& path, const LineRange& range,
                       const std::function<void(const std::string&, int)>& line_fn);

}  // namespace canopy::sim
