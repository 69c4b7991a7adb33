#pragma once
// record.jsonl (or record.jsonl.zst, the same lines compact): one JSON line per step with the
// truth, every UAV's pose and command, every scan
// (footprint membership, visibility, observations), every agent's fused tracks and occlusion map,
// and on planning epochs the team's plans and intention messages. Same seed, same bytes: wall
// times, which differ from run to run, go to timings.jsonl instead.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/output_file.h"
#include "sim/compact_record.h"
#include "sim/record_line.h"
#include "sim/record_lines.h"
#include "sim/step_observer.h"
#include "spec/scenario_spec.h"

namespace canopy::sim {

class RecordLineWriter;

class Recorder final : public StepObserver {
 public:
  /// Streams record.jsonl and timings.jsonl of `dir` into new temporaries (AtomicFile): nothing
  /// appears under either name until commit(), and a recorder destroyed without it leaves
  /// nothing. Throws WriteError when it cannot write. Each line is streamed into one reused
  /// buffer (no JSON document per step); the bytes are those of nlohmann's dump(). Keeps a copy
  /// of the spec's labels. `format` (automatic is resolved for `spec`): compact writes the same
  /// lines as record.jsonl.zst (compact_record.h) in blocks of `block`.
  Recorder(const std::filesystem::path& dir, const spec::ScenarioSpec& spec,
           RecordFormat format = RecordFormat::jsonl, BlockSize block = {});
  ~Recorder();
  void onStep(const StepRecord& record) override;
  /// Publishes both files, once, after the last step.
  void commit();

 private:
  AtomicFile record_;
  AtomicFile timings_;
  std::unique_ptr<RecordLineWriter> lines_;
  std::unique_ptr<CompactRecordWriter> compact_;  // the compact form's, else none
  std::string line_;
};

}  // namespace canopy::sim
