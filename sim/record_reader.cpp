#include "sim/record_reader.h"

#include <string>

#include "core/text_file.h"
#include "sim/record_step_reader.h"
#include "spec/error.h"
#include "spec/json_text.h"
#include "spec/loader.h"

namespace canopy::sim {
namespace {

namespace fs = std::filesystem;
using spec::Json;
using spec::ScenarioError;

// Bounded like a scenario file: a regular file (not a FIFO, device, directory or link) of at
// most kMaxJsonBytes.
std::string readResultFile(const fs::path& path, const std::string& what) {
  return spec::readResultText(path, "the " + what + " that `canopy run` writes",
                              spec::kMaxJsonBytes);
}

}  // namespace

spec::ScenarioSpec readManifest(const fs::path& path) {
  const Json manifest = spec::parseJson(readResultFile(path, "manifest"), path.string());
  if (!manifest.is_object() || !manifest.contains("effective_config") ||
      !manifest["effective_config"].is_object()) {
    throw ScenarioError(path.string(), "effective_config",
                        "expected an object (the run's scenario)");
  }
  return spec::loadScenarioText(manifest["effective_config"].dump(),
                                path.string() + ": effective_config");
}

std::vector<world::WorldSnapshot> readRecordTruth(const fs::path& path,
                                                  const spec::ScenarioSpec& spec,
                                                  const LineRange& range) {
  std::vector<world::WorldSnapshot> steps;
  forEachRecordStep(path, shapeOf(spec), range, [&](const StepRecord& record, int number) {
    world::WorldSnapshot& s = steps.emplace_back();
    truthSnapshot(record, s);
    for (std::size_t i = 0; i < spec.uavs.size(); ++i) {
      // A UAV with an altitude (issue 53) records it; the others fly at their fixed one.
      if (record.uavs[i].altitude) continue;
      if (spec.uavs[i].sensor.camera)
        failRecordLine(path.string(), number, "uavs." + std::to_string(i) + ".z", "a field 'z'");
      s.uavs[i].z = spec.uavs[i].body.z;
    }
  });
  if (steps.empty()) throw ScenarioError(path.string(), "", "has no steps");
  return steps;
}

RunRecord readRun(const fs::path& run_dir, const LineRange& range) {
  std::error_code error;
  if (!fs::is_directory(run_dir, error)) {
    throw ScenarioError(run_dir.string(), "",
                        "no such directory (expected the --out directory of `canopy run`)");
  }
  RunRecord run;
  run.spec = readManifest(run_dir / "manifest.json");
  run.truth = readRecordTruth(recordFileOf(run_dir), run.spec, range);
  return run;
}

}  // namespace canopy::sim
