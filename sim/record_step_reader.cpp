#include "sim/record_step_reader.h"

#include <optional>

#include "spec/error.h"
#include "spec/result_lines.h"

namespace canopy::sim {

RecordShape shapeOf(const spec::ScenarioSpec& spec) {
  return {spec.labels, spec.uavs.size(), spec.targets.size()};
}

void failRecordLine(const std::string& file, int line, const std::string& field,
                    const std::string& expected) {
  throw spec::ScenarioError(file,
                            "line " + std::to_string(line) + (field.empty() ? "" : ": " + field),
                            "expected " + expected);
}

void LineIn::fail(const At& at, const std::string& expected) const {
  failRecordLine(file, line, at.text(), expected);
}

void readStepLine(const std::string& text, const std::string& file, int number,
                  const RecordShape& shape, StepRecord& step, const RecordSchema& schema) {
  if (text.size() > spec::kMaxResultLineBytes)
    failRecordLine(file, number, "", "a line of at most 256 MiB (one step of `canopy run`)");
  const std::optional<spec::Json> json = spec::parseResultLine(text);  // std::bad_alloc: exit 1
  if (!json) {
    failRecordLine(file, number, "",
                   "one JSON object per line, nested at most " +
                       std::to_string(spec::kMaxJsonDepth) + " levels deep");
  }
  if (!json->is_object()) failRecordLine(file, number, "", "one JSON object per line");
  const LineIn in{schema, file, number, shape.labels, shape.uavs, shape.targets};
  step = StepRecord{};
  readObject(in, *json, schema.step, step, At{});
}

void forEachRecordStep(const std::filesystem::path& path, const RecordShape& shape,
                       const LineRange& range,
                       const std::function<void(const StepRecord&, int)>& step_fn) {
  const std::string file = path.string();
  StepRecord step;
  forEachRecordLine(path, range, [&](const std::string& line, int number) {
    readStepLine(line, file, number, shape, step);
    step_fn(step, number);
  });
}

}  // namespace canopy::sim
