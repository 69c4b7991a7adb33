#include "scenarios/run.h"

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/random.h"
#include "core/text_file.h"
#include "scenarios/recorder.h"
#include "scenarios/summary.h"

namespace canopy::scenarios {

std::string manifestJson(const ScenarioSpec& spec, const std::string& command_line) {
  using Json = nlohmann::json;
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx",
                static_cast<unsigned long long>(fnv1a64(spec.effective_config)));
  Json manifest;
  manifest["canopy_version"] = CANOPY_VERSION;
  manifest["scenario"] = spec.name;
  manifest["scenario_file"] = spec.file.string();
  manifest["config_hash_fnv1a64"] = hash;
  manifest["seed"] = spec.seed;
  manifest["command"] = command_line;
  manifest["labels"] = spec.labels;
  manifest["trees"] = spec.trees.size();
  manifest["effective_config"] = Json::parse(spec.effective_config);
  return manifest.dump(2);
}

RunResult runScenario(const ScenarioSpec& spec, const RunOptions& options) {
  std::filesystem::create_directories(options.out_dir);
  writeFileAtomically(options.out_dir / "manifest.json",
                      manifestJson(spec, options.command_line) + "\n");

  const auto start = std::chrono::steady_clock::now();
  Simulation sim(spec);
  Recorder recorder(options.out_dir.string());
  SummaryBuilder summary(spec);
  while (!sim.done()) {
    sim.tick();
    recorder.write(sim);
    summary.add(sim);
    if (options.on_step) options.on_step(sim);
  }
  RunResult result;
  result.steps = summary.steps();
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.summary_json = summary.json(result.wall_seconds);
  writeFileAtomically(options.out_dir / "summary.json", result.summary_json + "\n");
  return result;
}

}  // namespace canopy::scenarios
