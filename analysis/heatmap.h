#pragma once
// Sensitivity maps: for a sweep with two numeric axes, a grid of one behaviour figure per
// configuration — the fraction of trials in a named cooperative state at L (the Sankey's last
// column), or for occlusion scenarios without one the mean coverage of the occluded target while
// hidden — each with its 95 % interval. Where cooperation emerges and where it fades.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/figure.h"
#include "analysis/intervals.h"
#include "analysis/sweep_analysis.h"

namespace canopy::analysis {

/// What every cell of a map shows.
struct HeatmapMetric {
  std::string state;  // a state name: the fraction of trials in it at L; empty: a coverage
  double before_hiding_s = 0.0;  // > 0: coverage in the window this long before it hides
  std::string label;  // e.g. "fraction of trials in M* at L"
  double max = 1.0;   // the colour scale spans [0, max]
};


struct HeatmapCell {
  int trials = 0;
  Estimate value;
  std::string detail;  // hidden coverage: the target and its hidden interval, e.g. "I 2.2-5.0 s"
};

struct Heatmap {
  std::string x_path, y_path;                   // the two numeric axes
  std::vector<std::string> x_values, y_values;  // JSON text, in increasing numeric order
  std::vector<std::string> others;  // "path=value" of every other axis, fixed in this map
  HeatmapMetric metric;
  std::vector<std::vector<std::optional<HeatmapCell>>> cells;  // [y][x]; empty: no trials
  std::string stem;  // file name without extension, e.g. "heatmap_start.0_vs_horizon"
};

/// The metric of a sweep's maps: request.state when given (it must be one of the
/// configurations' ownership states, else ScenarioError naming `--state`); else, with
/// request.before_hiding_s > 0, the mean footprints on the target of each configuration's first
/// occluded interval over the steps in the last before_hiding_s seconds before it is hidden (the
/// reaction ahead of an occlusion; ScenarioError naming `--before-hiding` when no configuration
/// has an occlusion); else the named state "M*" when the scenario has one, else the coverage of
/// each configuration's first occluded interval while hidden when some configuration has one;
/// std::nullopt when none applies.
std::optional<HeatmapMetric> heatmapMetric(const SweepAnalysis& analysis,
                                           const HeatmapRequest& request = {});

/// x and y are the sweep's first two numeric axes (every value a JSON number); one map per
/// combination of the other axes' values, in sweep order. No maps with fewer than two.
std::vector<Heatmap> sensitivityMaps(const SweepAnalysis& analysis, const HeatmapMetric& metric);

/// The map as a table: one row per cell, y rows from the smallest value up.
///   x_path, x, y_path, y, <other axes' paths>, metric, trials, value, low, high, width, detail
std::string heatmapCsv(const Heatmap& map);

/// Cells coloured by value on the [0, metric.max] scale with the value and its interval written
/// in each, y increasing upwards, and a colour scale; under the title the metric and the other
/// axes' values. The cells are the figure's first
/// FilledPolygons, row by row from the smallest y, x increasing.
Figure heatmapFigure(const Heatmap& map, const std::string& title);

/// The colour scale: u ∈ [0, 1] from pale yellow through green to dark blue (clamped).
Colour heatColour(double u);

/// A JSON value as a reader sees it ("sma" for "\"sma\"", 5 for 5), and an override
/// "path=value" as "path = value".
std::string displayValue(const std::string& json);
std::string displayOverride(const std::string& override_text);

/// Writes <stem>.{csv,svg,pdf,png} per map into out_dir, figures in `style`; returns the maps
/// written.
std::vector<Heatmap> writeHeatmaps(const SweepAnalysis& analysis,
                                   const std::filesystem::path& out_dir,
                                   const HeatmapRequest& request = {},
                                   const FigureStyle& style = {});

/// Markdown embedding a sweep's maps for report.md: a heading, a line on what the cells show
/// and one image per map (figures_dir: where writeHeatmaps wrote them, relative to the report).
/// Empty when the sweep yields no map.
std::string heatmapMarkdown(const SweepAnalysis& analysis, const std::string& figures_dir,
                            const std::string& heading, const HeatmapRequest& request = {});

}  // namespace canopy::analysis
