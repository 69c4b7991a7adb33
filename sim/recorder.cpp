#include "sim/recorder.h"

#include <nlohmann/json.hpp>

#include "sim/record_line.h"

namespace canopy::sim {

Recorder::Recorder(const std::filesystem::path& dir, const spec::ScenarioSpec& spec,
                   RecordFormat format, BlockSize block)
    : record_(dir / (resolveRecordFormat(format, spec) == RecordFormat::compact
                         ? kRecordCompactName
                         : kRecordJsonlName)),
      timings_(dir / "timings.jsonl"),
      lines_(std::make_unique<RecordLineWriter>(spec.labels)) {
  if (resolveRecordFormat(format, spec) == RecordFormat::compact) {
    compact_ = std::make_unique<CompactRecordWriter>(
        [this](std::string_view bytes) { record_.write(bytes); }, block, spec.labels);
  }
}

Recorder::~Recorder() = default;

void Recorder::onStep(const StepRecord& record) {
  if (compact_) {
    compact_->append(record);
  } else {
    line_.clear();  // keeps its capacity: no allocation per step once the longest line was seen
    lines_->write(record, line_);
    line_ += '\n';
    record_.write(line_);
  }
  if (record.plan) {
    using Json = nlohmann::json;
    Json seconds = Json::array();
    for (const auto& report : record.plan->reports) seconds.push_back(report.seconds);
    timings_.write(
        Json{{"k", record.step}, {"epoch", record.plan->epoch}, {"plan_seconds", seconds}}.dump() +
        '\n');
  }
}

void Recorder::commit() {
  if (compact_) compact_->finish();
  record_.commit();
  timings_.commit();
}

}  // namespace canopy::sim
