#pragma once
// The paper's experiment table (scenarios.md, "Experiments the paper ran") as sweeps, and the
// numbers the paper reports for them.
#include <optional>
#include <string>
#include <vector>

#include "analysis/sweep_analysis.h"
#include "experiments/sweep.h"

namespace canopy::analysis {

/// One row group of the paper's table.
struct Experiment {
  // The sweep's name and directory: the library scenario's name for the paper's table (the
  // scenario itself is sweep.scenario), "joint_effect_learned" for its learned rows.
  std::string scenario;
  experiments::SweepSpec sweep;
  bool ownership = false;  // analysed by ownership (TH, RA) or by occlusion (JE, OS)
  HeatmapRequest maps;     // what its sensitivity maps show (default: M* or hidden coverage)
  bool timed = false;      // its planners' decision times are measured (decision_time.h)
  // Drawn as the team's figures per configuration (configuration_summary.h) instead of maps.
  bool team_summary = false;
};

/// A decision period (planner.replan_period, s) the occlusion experiments run with: every 1 s
/// (algorithms.md, the default) and at every 0.2 s simulation step with 1 s actions (the paper's
/// "SMA-NBO generates a plan … at every time step"), reported side by side.
struct DecisionPeriod {
  double seconds = 1.0;
  const char* label = "";  // "decisions every 1 s"
};
const std::vector<DecisionPeriod>& decisionPeriods();

/// TH and RA: SMA-NBO and Dec-POMDP × H ∈ {1, 5}; JE and OS: SMA-NBO, H = 5, × occlusion map
/// ∈ {a-priori, dynamic, none} × decision period; `trials` per configuration (the paper: 40, 560
/// trials in all). Then the learned planner's rows that are not the paper's: TH and RA carry it
/// on their planner axis; joint_effect_learned and occlusion_sharing_learned fly JE and OS with
/// it (the scenario's shipped policy, H = 5) over the same maps and decision periods.
std::vector<Experiment> paperExperiments(int trials, std::uint64_t seed);

/// The learned planner's held-out variants (scenarios/sweeps/learned_heldout.json: Trajectory
/// Handover turned, scaled and tiled to 4 and 6 UAVs, SMA-NBO beside the shipped policy) with
/// `trials` per configuration and the given seed; timed.
std::vector<Experiment> learnedStudies(int trials, std::uint64_t seed);

/// The sensitivity studies of scenarios/sweeps/ (ra_distance_horizon, je_occlusion_spacing,
/// je_reaction, altitude_tradeoff), with `trials` per configuration and the given seed;
/// `ownership` as above. altitude_tradeoff (issue 53) is a team summary: coverage, team OSPA
/// and people held at fixed altitudes and at free altitude, in a sparse and a dense forest.
std::vector<Experiment> sensitivityStudies(int trials, std::uint64_t seed);

/// What the paper reports for the frequency of the cooperative state M*_L (Sankey figures).
struct PaperOwnership {
  std::string scenario, algorithm;  // "sma" / "dec_pomdp"
  int horizon = 0;
  std::optional<double> at_half;  // fraction of trials in M* at k = L/2
  std::optional<double> at_end;   // … at k = L
  std::string note;
};
const std::vector<PaperOwnership>& paperOwnership();

/// What the paper reports for Joint Effect (Fig. 5): I is hidden from 2.2 s to 5.0 s; the
/// coverage of I changes at about 1.6 s with the a-priori map and at about 2.2 s with the dynamic
/// map ("a notable change delay at the blue line of 1.6 ∼ 2.2 second").
inline constexpr double kJointEffectHiding = 2.2;     // s
inline constexpr double kPaperReactionAPriori = 1.6;  // s
inline constexpr double kPaperReactionDynamic = 2.2;  // s

}  // namespace canopy::analysis
