#pragma once
// Load-time work limits. From a scenario's validated fields, the work one trial will do is
// bounded before any of it is allocated or run; a file that asks for more is a ScenarioError
// ("expected at most …, this file asks for about …") naming the field that drives it. The
// limits sit about a thousand times above the paper's scenarios; `--budget K` multiplies every
// one of them by K for those who mean it. The run's whole work is estimated in instructions,
// stage by stage (spec/work_model.h), and limited in CPU time: a file that runs in minutes is
// admitted, one that would take hours is refused with the figure.
#include <string>

#include "spec/scenario_spec.h"
#include "spec/work_model.h"

namespace canopy::spec {

/// Upper bounds, per trial unless said otherwise. A "unit" is one inner-loop term of that stage.
struct WorkLimits {
  double trees = 2e6;                 // points one layout generator draws; trees in a scenario
  double world_units = 2e9;           // steps × (sub-steps × (UAVs + targets) + UAVs · seen)
  double world_substeps = 1e7;        // steps × Box2D sub-steps a step (world/substeps.h)
  double record_bytes = 4e9;          // estimated size of the record as `canopy run` writes it
  double tracking_units = 5e11;       // steps × UAVs × (measurements² + joint-event cap); city_swarm asks 2.2e11
  double tracking_step_units = 5e8;   // one step, every UAV, worst case (bench/RESULTS.md, issue 47)
  // The whole run's estimated instructions (spec/work_model.h) in CPU-seconds of the machine the
  // estimate was measured on (kInstructionsPerCpuSecond): half an hour.
  double cpu_seconds = 1800.0;
  double sweep_configurations = 1e5;  // points of a sweep's Cartesian product
  double sweep_trials = 1e7;          // configurations × trials
  double sweep_bytes = 1e9;           // configurations × (their overrides' text + 4 kB)
};

/// The limits multiplied by `scale` (> 0).
WorkLimits workLimits(double scale = 1.0);

/// At most how many trees one scan can see: the largest number of tree centres in any square of
/// side 2 × the largest footprint's circumradius (every tree in a footprint is a detection, a
/// track and a line of the record). Counted on a grid of half that side, O(trees).
double visibleTreesBound(const ScenarioSpec& spec);
/// The most targets one footprint holds at any step (every target past 2·10⁶ positions to check).
double visibleTargetsBound(const ScenarioSpec& spec);

/// Scans a track born from clutter survives without a detection of its own, at most: existence
/// confirmation drops it once r < delete_existence, r ← existenceAfterMiss(p_S r) from
/// birth_existence per scan (agents/tracking/existence.h); m_of_n drops it after confirm_window
/// scans. At most the run's steps. With 200 clutter per scan and birth_existence 0.999 it is 6:
/// each UAV then holds ~1200 clutter tracks.
double clutterTrackScans(const ScenarioSpec& spec);

/// `canopy run --record auto` (the default) writes the compact record (record.jsonl.zst) when
/// record.jsonl is estimated above this many bytes, and plain lines below (sim/record_lines.h).
inline constexpr double kCompactRecordAbove = 64e6;
/// record.jsonl's estimate over this bounds the compact record's size: measured 49 (16 × 64 × 10⁴,
/// 30 s), 105 (city_swarm), 164 (64 × 256 × 10⁵) and 550 (256 × 1024 × 10⁶) (bench/RESULTS.md).
inline constexpr double kCompactRecordRatio = 20.0;

/// What one trial of `spec` asks for, in the units of WorkLimits.
struct WorkEstimate {
  double visible_trees = 0.0;    // visibleTreesBound
  double visible_targets = 0.0;  // visibleTargetsBound
  double substeps = 1.0;         // the most Box2D sub-steps of one step (world/substeps.h)
  double world_units = 0.0;
  double record_bytes = 0.0;          // record.jsonl, plain lines
  double record_written_bytes = 0.0;  // the form `--record auto` writes (kCompactRecordAbove)
  double tracking_units = 0.0;
  double clutter_track_scans = 0.0;  // clutterTrackScans
  double tracking_step_units = 0.0;  // one step, every UAV: joint events enumerated + clutter BP
  StageWork stages;          // estimated instructions per stage (spec/work_model.h)
  double instructions = 0.0;  // stages.total()
  double cpuSeconds() const { return instructions / kInstructionsPerCpuSecond; }
};
WorkEstimate estimateWork(const ScenarioSpec& spec);

/// "expected at most LIMIT WHAT, this file asks for about AMOUNT (--budget K raises the limit)".
std::string budgetMessage(double amount, double limit, const std::string& what);

/// Throws ScenarioError (spec.file, the driving field) when one trial of `spec` exceeds a limit.
void checkWork(const ScenarioSpec& spec, double budget_scale);

}  // namespace canopy::spec
