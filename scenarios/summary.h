#pragma once
// summary.json: what a run amounted to, accumulated step by step.
#include <string>
#include <vector>

#include "scenarios/simulation.h"

namespace canopy::scenarios {

class SummaryBuilder {
 public:
  explicit SummaryBuilder(const ScenarioSpec& spec);
  void add(const Simulation& sim);
  /// The summary as pretty JSON; `wall_seconds` goes under "timing" (the only non-deterministic
  /// field).
  std::string json(double wall_seconds) const;

  struct TargetTally {
    int steps_visible = 0;       // visible to at least one UAV
    int steps_in_footprint = 0;  // inside at least one footprint
    long coverage = 0;           // Σ_k number of footprints containing the target
  };
  struct UavTally {
    double distance = 0.0;       // m flown
    long visible = 0;            // Σ_k |V_{i,k}|
    long observations = 0;       // target, clutter and tree detections
  };
  const std::vector<TargetTally>& targets() const { return targets_; }
  const std::vector<UavTally>& uavs() const { return uavs_; }
  int steps() const { return steps_; }

 private:
  const ScenarioSpec& spec_;
  std::vector<TargetTally> targets_;
  std::vector<UavTally> uavs_;
  std::vector<Vec2> last_uav_position_;
  std::vector<int> visible_by_;      // scratch: per target, UAVs that see it this step
  std::vector<int> in_footprint_of_; // scratch: per target, footprints holding it this step
  int steps_ = 0;
};

}  // namespace canopy::scenarios
