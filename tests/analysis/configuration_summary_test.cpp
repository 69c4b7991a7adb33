// The team per configuration (issue 53): coverage, team OSPA and people held of each
// configuration from its trials, checked by hand on two configurations of two trials each, and
// the figure's categories and series from the sweep's axes.
#include "analysis/configuration_summary.h"

#include <gtest/gtest.h>

#include <cmath>
#include <variant>

namespace canopy::analysis {
namespace {

ConfigStatistics config(const std::string& altitude, const std::string& forest) {
  ConfigStatistics s;
  s.id = "altitude-" + altitude + "_forest-" + forest;
  s.point = {"altitude=\"" + altitude + "\"", "forest=\"" + forest + "\""};
  // Two trials, one person, four steps: covered at 3 of 4 steps, then at 1 of 4.
  s.trial_coverage = {{{1, 2, 0, 1}}, {{0, 0, 1, 0}}};
  s.trial_team_ospa = {2.0, 4.0};
  s.trial_held = {0.5, 1.0};
  s.trials = 2;
  return s;
}

TEST(ConfigurationSummary, TeamFiguresByHand) {
  SweepAnalysis analysis;
  analysis.configs = {config("fixed_20", "sparse"), config("free", "dense")};
  analysis.configs[1].trial_team_ospa = {1.0, 1.0, 1.0, 1.0, 1.0};  // five equal trials
  analysis.configs[1].trial_coverage.assign(5, {{1, 1, 1, 1}});
  analysis.configs[1].trial_held.assign(5, 1.0);
  const std::vector<ConfigurationSummary> rows = summariseConfigurations(analysis);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].category, "fixed_20");
  EXPECT_EQ(rows[0].series, "forest = sparse");
  EXPECT_EQ(rows[0].coverage.trials, 2);
  EXPECT_DOUBLE_EQ(rows[0].coverage.value, 0.5);  // (3/4 + 1/4) / 2
  EXPECT_DOUBLE_EQ(rows[0].team_ospa.value, 3.0);
  // t interval of two values 2 and 4: 3 ± t_{0.975,1} · s/√2, s = √2: 3 ± 12.706.
  EXPECT_NEAR(rows[0].team_ospa.ci.high, 3.0 + 12.7062047361747, 1e-6);
  EXPECT_DOUBLE_EQ(rows[0].team_ospa.ci.low, 0.0);  // clipped at 0
  EXPECT_DOUBLE_EQ(rows[0].held.value, 0.75);
  // Five trials all covered throughout: the point 1 (intervals.h, kMinTrialsForPoint).
  EXPECT_DOUBLE_EQ(rows[1].coverage.value, 1.0);
  EXPECT_DOUBLE_EQ(rows[1].coverage.ci.low, 1.0);
  EXPECT_DOUBLE_EQ(rows[1].team_ospa.ci.high, 1.0);

  const std::string md = configurationMarkdown(rows, "Fly higher?", "fig", "team_figures");
  EXPECT_NE(md.find("over 2–5 trials"), std::string::npos) << md;
  EXPECT_NE(md.find("| fixed_20, forest = sparse | 0.500 ["), std::string::npos) << md;
  EXPECT_NE(md.find("](fig/team_figures.png)"), std::string::npos);

  const Figure figure = configurationFigure(rows, "title");
  int categories = 0, series = 0;
  for (const Shape& shape : figure.shapes) {
    if (const Label* label = std::get_if<Label>(&shape)) {
      categories += label->text == "fixed_20" || label->text == "free";
      series += label->text == "forest = sparse" || label->text == "forest = dense";
    }
  }
  EXPECT_EQ(categories, 6);  // under each of the three panels
  EXPECT_EQ(series, 2);      // the legend
}

TEST(ConfigurationSummary, NoTeamFiguresLeaveThoseColumnsEmpty) {
  SweepAnalysis analysis;
  analysis.configs = {config("fixed_20", "sparse")};
  analysis.configs[0].trial_team_ospa.clear();
  analysis.configs[0].trial_held.clear();
  const std::vector<ConfigurationSummary> rows = summariseConfigurations(analysis);
  EXPECT_EQ(rows[0].team_ospa.trials, 0);
  EXPECT_EQ(rows[0].held.trials, 0);
  EXPECT_NE(configurationMarkdown(rows, "h", "f", "s").find("| — | — |"), std::string::npos);
}

}  // namespace
}  // namespace canopy::analysis
