#pragma once
// record.jsonl: one JSON line per step with the truth, every UAV's pose and command, every scan
// (footprint membership, visibility, observations), every agent's fused tracks and occlusion map,
// and on planning epochs the team's plans and intention messages. Same seed, same bytes: wall
// times, which differ from run to run, go to timings.jsonl instead.
#include <fstream>
#include <string>

#include "scenarios/simulation.h"

namespace canopy::scenarios {

class Recorder {
 public:
  /// Opens (truncates) record.jsonl and timings.jsonl in `dir`; throws std::runtime_error when
  /// it cannot.
  explicit Recorder(const std::string& dir);
  void write(const Simulation& sim);

 private:
  std::ofstream record_;
  std::ofstream timings_;
};

/// One step as a JSON line (without the newline).
std::string recordLine(const Simulation& sim);

}  // namespace canopy::scenarios
