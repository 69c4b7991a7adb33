#include "sim/record_lines.h"

#include <algorithm>

#include "sim/compact_record.h"
#include "spec/budget.h"
#include "spec/json_text.h"

namespace canopy::sim {

RecordFormat resolveRecordFormat(RecordFormat format, const spec::ScenarioSpec& spec) {
  if (format != RecordFormat::automatic) return format;
  return spec::estimateWork(spec).record_bytes > kCompactRecordAbove ? RecordFormat::compact
                                                                     : RecordFormat::jsonl;
}

std::filesystem::path recordFileOf(const std::filesystem::path& run_dir) {
  const std::filesystem::path compact = run_dir / kRecordCompactName;
  std::error_code error;
  if (std::filesystem::exists(std::filesystem::symlink_status(compact, error))) return compact;
  return run_dir / kRecordJsonlName;
}

namespace {

// The non-blank lines of `text` (whole lines), numbered from `number` + 1, positions from
// `position`; those within `range` go to line_fn. Returns the position after the last.
std::uint64_t eachLine(const std::string& text, int& number, std::uint64_t position,
                       const LineRange& range,
                       const std::function<void(const std::string&, int)>& line_fn) {
  std::size_t next = 0;
  while (next < text.size() && position < range.end) {
    const std::size_t end = std::min(text.find('\n', next), text.size());
    ++number;
    const std::string line = text.substr(next, end - next);
    next = end + 1;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (position >= range.first) line_fn(line, number);
    ++position;
  }
  return position;
}

}  // namespace

void forEachRecordLine(const std::filesystem::path& path, const LineRange& range,
                       const std::function<void(const std::string&, int)>& line_fn) {
  int number = 0;
  if (path.extension() != ".zst") {
    const std::string text =
        spec::readResultText(path, "the record that `canopy run` writes", spec::kMaxResultBytes);
    eachLine(text, number, 0, range, line_fn);
    return;
  }
  const CompactRecordReader reader(path);
  for (std::size_t i = 0; i < reader.blocks().size(); ++i) {
    const RecordBlock& b = reader.blocks()[i];
    const std::uint64_t end = std::uint64_t{b.first_line} + b.lines;
    if (b.first_line >= range.end) break;
    if (end <= range.first) {  // not decoded: its lines are counted from the index
      number += static_cast<int>(b.lines);
      continue;
    }
    if (reader.version() == 1) {
      eachLine(reader.decode(i), number, b.first_line, range, line_fn);
      continue;
    }
    // Version 2: one line per step, none blank.
    const std::uint64_t skip = std::max(range.first, std::uint64_t{b.first_line}) - b.first_line;
    number += static_cast<int>(skip);
    std::uint64_t position = b.first_line + skip;
    reader.eachStepLine(i, static_cast<std::uint32_t>(skip), [&](const std::string& line) {
      if (position >= range.end) return false;
      line_fn(line, ++number);
      ++position;
      return true;
    });
  }
}

}  // namespace canopy::sim
