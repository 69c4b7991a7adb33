#pragma once
// `canopy analyze`: a sweep directory → per-configuration statistics → CSV tables (and, through
// figures.h, the figures behind them).
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/sweep_statistics.h"
#include "scenarios/spec.h"

namespace canopy::analysis {

struct SweepAnalysis {
  std::string name;                            // the sweep's name
  std::vector<scenarios::ScenarioSpec> specs;  // per configuration
  std::vector<ConfigStatistics> configs;  // per configuration, in sweep order (those with trials)
};

/// Loads every finished trial of the sweep in `sweep_dir` and summarises each configuration.
/// Throws ScenarioError when the directory is not a sweep or a trial file is malformed.
SweepAnalysis analyseSweep(const std::filesystem::path& sweep_dir);

/// Writes the CSV tables behind every figure into out_dir:
///   ownership_states.csv  config, column, step, t_s, state, trials, fraction
///   ownership_flows.csv   config, from_column, to_column, from_state, to_state, trials
///   ownership_changes.csv config, from_uav, to_uav, target, trials, fraction
///   occlusion_aware.csv   config, target, hidden_from_s, hidden_to_s, trials, p_aware,
///                         trials_with_event, p_aware_given_event
///   coverage.csv          config, target, step, t_s, mean_coverage, occluded
///   tracking.csv          config, step, t_s, mean_ospa_m, mean_trace_pos_m2
void writeTables(const SweepAnalysis& analysis, const std::filesystem::path& out_dir);

}  // namespace canopy::analysis

namespace canopy::analysis {

/// Writes sankey_<config>.{svg,png} per configuration and coverage.{svg,png} (one line per
/// configuration, one panel per trajectory) into out_dir.
void writeFigures(const SweepAnalysis& analysis, const std::filesystem::path& out_dir);

}  // namespace canopy::analysis
