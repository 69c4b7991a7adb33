#pragma once
// The paper's figures from sweep statistics: Sankey diagrams of ownership over the Sankey columns
// (one per configuration) and coverage curves per trajectory with its occluded intervals shaded
// (one line per configuration, e.g. per map mode).
#include <string>
#include <vector>

#include "analysis/figure.h"
#include "analysis/sweep_statistics.h"

namespace canopy::analysis {

/// Nodes: the ownership states present at k = 0, L/4, L/2, 3L/4, L, heights ∝ frequency; bands:
/// the trials moving between states of consecutive columns.
Figure sankeyFigure(const ConfigStatistics& stats, const std::string& title);

/// At most this many curves share a coverage panel.
inline constexpr int kSeriesPerPanel = 4;

/// The panel (facet) of each of `configs` configurations: all in one up to kSeriesPerPanel, else
/// split in order into ⌈configs / kSeriesPerPanel⌉ panels as even as can be (6 → 3 + 3).
std::vector<int> coverageFacets(int configs);

/// The marker of the series in place `index` of its panel (disc, square, triangle, diamond), a
/// convex polygon of radius about r px around `at`.
std::vector<Vec2> seriesMarker(int index, const Vec2& at, double r);

/// One panel per target, or per target and facet (coverageFacets) with more than
/// kSeriesPerPanel configurations: the mean number of footprints holding it over time, one line
/// per configuration (labels[c] names configs[c]) in a band of its 95 % interval, occluded
/// intervals (of the first configuration) shaded grey. Within a panel each line has its own
/// colour, dash pattern and marker (markers staggered in time, so that equal curves stay visible).
Figure coverageFigure(const std::vector<const ConfigStatistics*>& configs,
                      const std::vector<std::string>& labels,
                      const std::vector<std::string>& target_names, const std::string& title);

/// The colour of ownership state `index` of ConfigStatistics::states (named states first, then
/// "Miss 1", "Miss >1", "Other" with fixed colours).
Colour stateColour(const ConfigStatistics& stats, int index);

}  // namespace canopy::analysis
