#pragma once
// summary.json: what a run amounted to, accumulated step by step.
#include <cstdint>
#include <string>
#include <vector>

#include "agents/fusion/fusion_diagnostics.h"
#include "agents/planning/intention_links.h"
#include "metrics/ospa.h"
#include "sim/team_metrics.h"
#include "sim/step_observer.h"
#include "spec/scenario_spec.h"

namespace canopy::sim {

/// Keeps values only: the names it reports, copied from the spec, and the team's counts as of the
/// last step added; it holds no reference to the spec, a record or the simulation.
class SummaryBuilder final : public StepObserver {
 public:
  explicit SummaryBuilder(const spec::ScenarioSpec& spec);
  void onStep(const StepRecord& record) override;
  /// The summary as pretty JSON; wall times go under "timing" (the only non-deterministic
  /// fields).
  std::string json(double wall_seconds) const;

  struct TargetTally {
    int steps_visible = 0;       // visible to at least one UAV
    int steps_in_footprint = 0;  // inside at least one footprint
    long coverage = 0;           // Σ_k number of footprints containing the target
  };
  struct UavTally {
    double distance = 0.0;  // m flown
    long visible = 0;       // Σ_k |V_{i,k}|
    long observations = 0;  // target, clutter and tree detections
    long contacts = 0;      // contacts begun: a body touched that it did not touch the step before
    int steps_in_contact = 0;  // steps during which it touched something
    int contact_run = 0;       // steps in contact up to the last step, in a row
    int longest_contact = 0;   // the longest such run (steps), and the step it began
    int longest_contact_from = 0;
  };
  const std::vector<TargetTally>& targets() const { return targets_; }
  const std::vector<UavTally>& uavs() const { return uavs_; }
  int steps() const { return steps_; }
  /// ospa()[i][k]: OSPA (c = 50 m, p = 2) between the true target positions and agent i's
  /// confirmed track positions at step k (m).
  const std::vector<std::vector<double>>& ospa() const { return ospa_; }
  /// Per step: the team's figures (sim/team_metrics.h).
  const std::vector<TeamFigures>& team() const { return team_; }

 private:
  struct Names {
    std::string scenario;
    std::uint64_t seed = 0;
    double dt = 0.0;  // s
    std::size_t trees = 0;
    std::vector<std::string> targets, target_labels, uavs;
  };
  Names names_;
  std::vector<TargetTally> targets_;
  std::vector<UavTally> uavs_;
  std::vector<Vec2> last_uav_position_;
  std::vector<int> visible_by_;       // scratch: per target, UAVs that see it this step
  std::vector<int> in_footprint_of_;  // scratch: per target, footprints holding it this step
  metrics::CutoffAssignment assignment_{50.0, 2.0};  // OSPA and GOSPA (α = 2), c = 50 m, p = 2
  metrics::CellGrid truth_grid_;                     // the people's positions, per step
  std::vector<std::vector<double>> ospa_;            // [agent][k], m
  std::vector<std::vector<double>> gospa_;           // [agent][k], m
  // Region of interest: the people and tracks within interest_range of the agent (∞: all of
  // them, and the figures are ospa_'s).
  double interest_range_;
  std::vector<std::vector<double>> roi_ospa_;  // [agent][k], m
  std::vector<Vec2> roi_truth_, roi_estimates_;
  TeamMetrics team_metrics_;
  std::vector<TeamFigures> team_;      // [k]
  std::vector<char> held_;             // scratch: per person, held this step
  std::vector<int> steps_held_;        // [person]
  std::vector<long> false_tracks_;  // [agent]: Σ_k confirmed tracks with no target within c
  std::vector<std::vector<double>> plan_seconds_;  // [agent][epoch], s
  std::vector<Vec2> truth_positions_, estimates_;  // scratch
  struct AgentFigures {
    double ospa = 0.0, gospa = 0.0;
    int false_estimates = 0;
  };
  AgentFigures solved_;                  // the step's last solve: its figures
  std::vector<Vec2> solved_estimates_;   // and its estimates
  std::vector<AgentCounts> counts_at_end_;         // the last step's; empty until a step was added
  agents::fusion::FusionDiagnostics fusion_at_end_;
  agents::planning::MessageCounts intentions_at_end_;
  int steps_ = 0;
};

}  // namespace canopy::sim
