#pragma once
// One Monte Carlo trial: a scenario run to its end, kept as the compact per-step facts the
// behaviour analysis needs (no record.jsonl).
#include <cstdint>
#include <string>
#include <vector>

#include "metrics/ospa.h"
#include "sim/step_observer.h"
#include "sim/team_metrics.h"
#include "spec/scenario_spec.h"

namespace canopy::experiments {

/// Per-step sets of targets are bit masks (bit t ⇔ target t); trials with more than 64 targets
/// keep no masks.
using TargetBits = std::uint64_t;

struct TrialResult {
  std::string scenario;
  std::string config_id;  // the sweep configuration it belongs to
  std::uint64_t seed = 0;
  double dt = 0.0;  // s
  int uavs = 0, targets = 0, trees = 0;
  std::vector<std::vector<TargetBits>> visible;       // [k][i]: V_{i,k}
  std::vector<std::vector<TargetBits>> in_footprint;  // [k][i]: targets whose truth lies in φ_{i,k}
  std::vector<TargetBits> occluded;                   // [k]: targets strictly under a crown
  std::vector<int> tree_first_seen;  // per tree: first step a footprint held its centre, −1 never
  std::vector<double> ospa;          // [k]: OSPA (c 50 m, p 2) averaged over agents (m)
  std::vector<double> trace;  // [k]: Σ_j tr(P_pos) of confirmed tracks, averaged over agents (m²)
  // [k]: the team's figures (sim/team_metrics.h): team OSPA (m) and the fraction of people held.
  // Empty in a trial file written before they existed.
  std::vector<double> team_ospa, held;
  std::vector<double> plan_seconds;  // every planning call's wall time (s); not written
  double wall_seconds = 0.0;         // not part of the result's identity

  int steps() const { return static_cast<int>(occluded.size()); }
};

/// Accumulates a TrialResult step by step from a run's records.
class TrialCollector final : public sim::StepObserver {
 public:
  explicit TrialCollector(const spec::ScenarioSpec& spec);
  void onStep(const sim::StepRecord& record) override;
  TrialResult take() { return std::move(result_); }

 private:
  TrialResult result_;
  bool masks_ = true;
  metrics::Ospa ospa_{50.0, 2.0};
  sim::TeamMetrics team_;
  std::vector<Vec2> truth_, estimates_;  // scratch
};

/// Runs `spec` (its seed included) to the end and collects the trial.
TrialResult runTrial(const spec::ScenarioSpec& spec, const std::string& config_id);

/// JSON text of a trial, and back. The text is deterministic (wall times excluded), so identical
/// trials give identical files.
std::string trialToJson(const TrialResult& trial);
/// Throws ScenarioError naming `file` when the text is not a trial.
TrialResult trialFromJson(const std::string& text, const std::string& file);

}  // namespace canopy::experiments
