#pragma once
// record.jsonl: one JSON line per step with the truth, every UAV's pose and command, and every
// scan (footprint membership, visibility, observations). Same seed, same bytes.
#include <fstream>
#include <string>

#include "scenarios/simulation.h"

namespace canopy::scenarios {

class Recorder {
 public:
  /// Opens (truncates) the file; throws std::runtime_error when it cannot.
  explicit Recorder(const std::string& path);
  void write(const Simulation& sim);

 private:
  std::ofstream out_;
};

/// One step as a JSON line (without the newline).
std::string recordLine(const Simulation& sim);

}  // namespace canopy::scenarios
