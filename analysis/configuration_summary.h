#pragma once
// The team's figures per configuration of a sweep, each over its trials with a 95 % interval:
// coverage (the fraction of (person, step) pairs inside some footprint), team OSPA and people
// held (each averaged over the run). `canopy reproduce` answers "should my team fly higher over
// this forest?" with them (issue 53: the altitude_tradeoff study; docs/design-notes.md, "Height").
#include <string>
#include <vector>

#include "analysis/figure.h"
#include "analysis/intervals.h"
#include "analysis/sweep_analysis.h"

namespace canopy::analysis {

struct ConfigurationSummary {
  std::string config;    // the sweep configuration's id
  std::string category;  // its value on the sweep's first axis (the figure's x)
  std::string series;    // its values on the other axes, "name = value, …" (one series each)
  Estimate coverage;     // fraction of (person, step) pairs in some footprint, per trial, in [0, 1]
  Estimate team_ospa;    // m, per trial the mean over steps of the team OSPA
  Estimate held;         // per trial the mean over steps of the fraction of people held, [0, 1]
};

/// The file stem of the figure `canopy reproduce` draws for a team-summary study.
inline constexpr const char* kTeamSummaryStem = "team_figures";

/// Per configuration, in sweep order. Team OSPA and held are left at 0 trials when the trial
/// files carry no team figures.
std::vector<ConfigurationSummary> summariseConfigurations(const SweepAnalysis& analysis);

/// Three panels (coverage, team OSPA, held), the first axis's values across, one series per
/// combination of the other axes: each mean a marker, its 95 % interval a bar.
Figure configurationFigure(const std::vector<ConfigurationSummary>& rows, const std::string& title);

/// The table in Markdown, a heading, the figure <figures_dir>/<stem>.png, and how many trials.
std::string configurationMarkdown(const std::vector<ConfigurationSummary>& rows,
                                  const std::string& heading, const std::string& figures_dir,
                                  const std::string& stem);

}  // namespace canopy::analysis
