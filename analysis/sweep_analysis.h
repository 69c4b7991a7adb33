#pragma once
// `canopy analyze`: a sweep directory → per-configuration statistics → CSV tables (and, through
// figures.h, the figures behind them).
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/figure_style.h"

#include "analysis/sweep_statistics.h"
#include "experiments/sweep.h"
#include "spec/scenario_spec.h"

namespace canopy::analysis {

struct SweepAnalysis {
  std::string name;                          // the sweep's name
  std::filesystem::path dir;                 // the sweep directory it was read from
  std::vector<experiments::SweepAxis> axes;  // the sweep's axes
  std::vector<spec::ScenarioSpec> specs;     // per configuration
  std::vector<ConfigStatistics> configs;  // per configuration, in sweep order (those with trials)
};

/// Loads every finished trial of the sweep in `sweep_dir` and summarises each configuration.
/// Throws ScenarioError when the directory is not a sweep or a trial file is malformed.
SweepAnalysis analyseSweep(const std::filesystem::path& sweep_dir,
                           const spec::LoadOptions& load = {});

/// Writes the CSV tables behind every figure into out_dir. Every proportion has its 95 % Wilson
/// interval (_low, _high) and every mean over trials its 95 % Student-t interval (±inf with a
/// single trial):
///   ownership_states.csv  config, column, step, t_s, state, trials, fraction (low, high),
///                         reached_trials, reached_fraction (low, high) — trials in the state at
///                         some step ≤ the column's (named states only)
///   ownership_flows.csv   config, from_column, to_column, from_state, to_state, trials
///   ownership_changes.csv config, from_uav, to_uav, target, trials, fraction (low, high)
///   occlusion_aware.csv   config, target, hidden_from_s, hidden_to_s, trials, p_aware (low,
///                         high), trials_with_event, p_aware_given_event (low, high),
///                         mean_coverage_hidden (low, high): footprints on the target while hidden
///   coverage.csv          config, target, step, t_s, mean_coverage (low, high), occluded
///   tracking.csv          config, step, t_s, mean_ospa_m (low, high), mean_trace_pos_m2 (low,
///                         high)
///   team.csv              (when hasTeamFigures) config, trials, coverage (low, high),
///                         team_ospa_m (low, high), held (low, high): configuration_summary.h
void writeTables(const SweepAnalysis& analysis, const std::filesystem::path& out_dir);

/// Whether every configuration's trials carry the team's figures (team OSPA, people held).
bool hasTeamFigures(const SweepAnalysis& analysis);

}  // namespace canopy::analysis

namespace canopy::analysis {

/// What a user asks the sensitivity maps to show (`analyze --state NAME`, `--before-hiding S`);
/// empty: the default of heatmapMetric (heatmap.h).
struct HeatmapRequest {
  std::string state;
  double before_hiding_s = 0.0;  // s
};

/// Writes sankey_<config>.{svg,png} per configuration, coverage.{svg,png} (one line per
/// configuration with its 95 % band, one panel per trajectory) and, for a sweep with two numeric
/// axes, the sensitivity maps heatmap_*.{csv,svg,png} (heatmap.h; `maps` picks what their cells
/// show, by default M* or the hidden coverage) into out_dir, each also as PDF, all in `style`;
/// and, when the trials carry team figures, team_figures.{svg,png,pdf}: each configuration's team
/// coverage, team OSPA and people held with their 95 % intervals (configuration_summary.h).
void writeFigures(const SweepAnalysis& analysis, const std::filesystem::path& out_dir,
                  const HeatmapRequest& maps = {}, const FigureStyle& style = {});

}  // namespace canopy::analysis
