// Sensitivity maps from hand-made configuration statistics: which cell holds which value, its
// colour on the scale, the CSV behind it, and the metric a sweep gets.
#include "analysis/heatmap.h"

#include <gtest/gtest.h>

#include "spec/error.h"

namespace canopy::analysis {
namespace {

spec::ScenarioSpec spec(bool with_m_star) {
  spec::ScenarioSpec s;
  s.uavs.resize(2);
  s.targets.resize(2);
  s.targets[0].name = "I";
  s.targets[1].name = "II";
  s.analysis.states = {{"M0", {{0}, {1}}, false}};
  if (with_m_star) s.analysis.states.push_back({"M*", {{1}, {0}}, false});
  return s;
}

// A configuration of 40 trials of which `in_m_star` end (k = L) in M*.
ConfigStatistics config(const std::vector<std::string>& overrides, int in_m_star) {
  ConfigStatistics s;
  s.id = overrides.back();
  s.overrides = overrides;
  s.trials = 40;
  s.uavs = 2;
  s.states = {"M0", "M*", "Miss 1", "Miss >1", "Other"};
  for (auto& counts : s.state_counts) counts.assign(5, 0);
  s.state_counts[4] = {40 - in_m_star, in_m_star, 0, 0, 0};
  return s;
}

// Axes: the algorithm (not numeric), a distance (numeric, listed out of order) and the horizon.
// The SMA configuration at distance 30, H = 5 has no trials.
SweepAnalysis threeAxisSweep() {
  SweepAnalysis a;
  a.name = "study";
  a.axes = {{"planner.algorithm", {"\"sma\"", "\"dec_pomdp\""}, {}},
            {"x.distance", {"30", "20"}, {}},
            {"planner.horizon", {"1", "5"}, {}}};
  const int m_star[2][2][2] = {{{20, -1}, {0, 40}}, {{10, 10}, {10, 10}}};  // [alg][dist][H]
  const char* algorithms[] = {"\"sma\"", "\"dec_pomdp\""};
  const char* distances[] = {"30", "20"};
  const char* horizons[] = {"1", "5"};
  for (int g = 0; g < 2; ++g) {
    for (int d = 0; d < 2; ++d) {
      for (int h = 0; h < 2; ++h) {
        if (m_star[g][d][h] < 0) continue;
        a.configs.push_back(
            config({"fusion.rounds=3", std::string("planner.algorithm=") + algorithms[g],
                    std::string("x.distance=") + distances[d],
                    std::string("planner.horizon=") + horizons[h]},
                   m_star[g][d][h]));
        a.specs.push_back(spec(true));
      }
    }
  }
  return a;
}

bool sameColour(const Colour& a, const Colour& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b;
}

TEST(HeatColour, InterpolatesLinearlyBetweenItsFourAnchors) {
  EXPECT_TRUE(sameColour(heatColour(0.0), {255, 250, 205}));
  EXPECT_TRUE(sameColour(heatColour(1.0), {30, 50, 130}));
  EXPECT_TRUE(sameColour(heatColour(2.0), {30, 50, 130}));  // clamped
  // u = 1/2: halfway from (160, 215, 150) to (50, 150, 170) → (105, 182.5 → 183, 160).
  EXPECT_TRUE(sameColour(heatColour(0.5), {105, 183, 160}));
  // u = 1/4: 3/4 of the way from (255, 250, 205) to (160, 215, 150) → (183.75, 223.75, 163.75).
  EXPECT_TRUE(sameColour(heatColour(0.25), {184, 224, 164}));
}

TEST(SensitivityMaps, OneMapPerValueOfTheOtherAxesWithSortedNumericAxes) {
  const SweepAnalysis a = threeAxisSweep();
  const std::optional<HeatmapMetric> metric = heatmapMetric(a);
  ASSERT_TRUE(metric);
  EXPECT_EQ(metric->state, "M*");
  const std::vector<Heatmap> maps = sensitivityMaps(a, *metric);
  ASSERT_EQ(maps.size(), 2u);
  const Heatmap& sma = maps[0];
  EXPECT_EQ(sma.stem, "heatmap_distance_vs_horizon_algorithm-sma");
  EXPECT_EQ(maps[1].stem, "heatmap_distance_vs_horizon_algorithm-dec_pomdp");
  EXPECT_EQ(sma.x_path, "x.distance");
  EXPECT_EQ(sma.x_values, (std::vector<std::string>{"20", "30"}));
  EXPECT_EQ(sma.y_values, (std::vector<std::string>{"1", "5"}));
  // [y][x]: H = 1: distance 20 → 0/40, 30 → 20/40; H = 5: 20 → 40/40, 30 → no trials.
  ASSERT_TRUE(sma.cells[0][0] && sma.cells[0][1] && sma.cells[1][0]);
  EXPECT_FALSE(sma.cells[1][1]);
  EXPECT_EQ(sma.cells[0][0]->value.value, 0.0);
  EXPECT_EQ(sma.cells[0][1]->value.value, 0.5);
  EXPECT_EQ(sma.cells[1][0]->value.value, 1.0);
  EXPECT_NEAR(sma.cells[0][1]->value.ci.low, 0.3519953, 1e-6);  // Wilson 20/40
}

TEST(HeatmapFigure, CellsAreColouredRowByRowFromTheSmallestY) {
  const SweepAnalysis a = threeAxisSweep();
  const Heatmap sma = sensitivityMaps(a, *heatmapMetric(a))[0];
  const Figure f = heatmapFigure(sma, "study");
  std::vector<FilledPolygon> cells;
  for (const Shape& shape : f.shapes) {
    if (const auto* p = std::get_if<FilledPolygon>(&shape); p && cells.size() < 4)
      cells.push_back(*p);
  }
  ASSERT_EQ(cells.size(), 4u);
  EXPECT_TRUE(sameColour(cells[0].fill, heatColour(0.0)));  // H = 1, distance 20
  EXPECT_TRUE(sameColour(cells[1].fill, heatColour(0.5)));  // H = 1, distance 30
  EXPECT_TRUE(sameColour(cells[2].fill, heatColour(1.0)));  // H = 5, distance 20
  EXPECT_TRUE(sameColour(cells[3].fill, {225, 225, 225}));  // H = 5, distance 30: no trials
  // y grows upwards: the H = 5 row is drawn above the H = 1 row, x grows to the right.
  EXPECT_LT(cells[2].points[0].y(), cells[0].points[0].y());
  EXPECT_GT(cells[1].points[0].x(), cells[0].points[0].x());
  // Each cell writes its value and Wilson interval: 20/40 → 0.50 [0.35, 0.65].
  bool value = false, interval = false;
  for (const Shape& shape : f.shapes) {
    if (const auto* l = std::get_if<Label>(&shape)) {
      value |= l->text == "0.50";
      interval |= l->text == "[0.35, 0.65]";
    }
  }
  EXPECT_TRUE(value);
  EXPECT_TRUE(interval);
}

TEST(HeatmapCsv, OneRowPerCellWithTheOtherAxesAndTheIntervalWidth) {
  const SweepAnalysis a = threeAxisSweep();
  const Heatmap sma = sensitivityMaps(a, *heatmapMetric(a))[0];
  // Wilson bounds (python3, closed form): 0/40 [0, 0.0876216], 20/40 [0.351995, 0.648005],
  // 40/40 [0.912378, 1].
  EXPECT_EQ(heatmapCsv(sma),
            "x_path,x,y_path,y,\"planner.algorithm\",metric,trials,value,low,high,width,detail\n"
            "\"x.distance\",20,\"planner.horizon\",1,\"sma\",\"fraction of trials in M* at L\",40,"
            "0,0,0.0876216,0.0876216,\"\"\n"
            "\"x.distance\",30,\"planner.horizon\",1,\"sma\",\"fraction of trials in M* at L\",40,"
            "0.5,0.351995,0.648005,0.296009,\"\"\n"
            "\"x.distance\",20,\"planner.horizon\",5,\"sma\",\"fraction of trials in M* at L\",40,"
            "1,0.912378,1,0.0876216,\"\"\n"
            "\"x.distance\",30,\"planner.horizon\",5,\"sma\",\"fraction of trials in M* at L\",0,"
            ",,,,\n");
}

TEST(HeatmapMetric, OcclusionScenariosWithoutMStarMapTheHiddenCoverage) {
  SweepAnalysis a;
  a.name = "je";
  a.axes = {{"a", {"1"}, {}}, {"b", {"2"}, {}}};
  ConfigStatistics s = config({"a=1", "b=2"}, 0);
  s.trials = 2;
  s.dt = 0.2;
  s.occlusions = {OcclusionStatistics{}};
  s.occlusions[0].target = 0;
  s.occlusions[0].hidden = {1, 2};
  s.trial_coverage = {{{0, 2, 2, 0}, {0, 0, 0, 0}}, {{0, 1, 1, 0}, {0, 0, 0, 0}}};
  a.configs = {s};
  a.specs = {spec(false)};
  const std::optional<HeatmapMetric> metric = heatmapMetric(a);
  ASSERT_TRUE(metric);
  EXPECT_TRUE(metric->state.empty());
  EXPECT_EQ(metric->max, 2.0);  // two UAVs: at most two footprints
  const std::vector<Heatmap> maps = sensitivityMaps(a, *metric);
  ASSERT_EQ(maps.size(), 1u);
  // Per-trial means over steps 1..2: 2 and 1 → 1.5, s = √0.5; on the logit scale of x/2
  // (intervals.h): u = 3/4, se_η = (√0.5/2) / (√2 · 3/16) = 4/3, 2 · σ(ln 3 ∓ 12.7062047 · 4/3)
  // = [2.63333e−7, 1.99999997] (python3): inside the two UAVs' [0, 2], and nearly all of it.
  const HeatmapCell& cell = *maps[0].cells[0][0];
  EXPECT_DOUBLE_EQ(cell.value.value, 1.5);
  EXPECT_NEAR(cell.value.ci.low, 2.63333e-7, 1e-11);
  EXPECT_NEAR(cell.value.ci.high, 1.99999997, 1e-8);
  EXPECT_GT(cell.value.ci.low, 0.0);
  EXPECT_LT(cell.value.ci.high, 2.0);
  EXPECT_EQ(cell.detail, "I 0.2-0.4 s");
}

// The coverage just before the first hidden step: hidden from step 3, a 0.4 s window at dt
// 0.2 s is steps 1..2 (by hand: trial means (2 + 1)/2 = 1.5 and (1 + 0)/2 = 0.5 → 1.0).
TEST(HeatmapMetric, BeforeHidingAveragesTheWindowBeforeTheFirstHiddenStep) {
  SweepAnalysis a;
  a.name = "je";
  a.axes = {{"a", {"1"}, {}}, {"b", {"2"}, {}}};
  ConfigStatistics s = config({"a=1", "b=2"}, 0);
  s.trials = 2;
  s.dt = 0.2;
  s.occlusions = {OcclusionStatistics{}};
  s.occlusions[0].target = 0;
  s.occlusions[0].hidden = {3, 4};
  s.trial_coverage = {{{9, 2, 1, 9, 9}, {0, 0, 0, 0, 0}}, {{9, 1, 0, 9, 9}, {0, 0, 0, 0, 0}}};
  a.configs = {s};
  a.specs = {spec(true)};  // a named M* does not take precedence over the request
  const std::optional<HeatmapMetric> metric = heatmapMetric(a, {"", 0.4});
  ASSERT_TRUE(metric);
  EXPECT_EQ(metric->before_hiding_s, 0.4);
  EXPECT_EQ(metric->label,
            "mean footprints on the occluded target in the 0.4 s before it is hidden");
  const std::vector<Heatmap> maps = sensitivityMaps(a, *metric);
  const HeatmapCell& cell = *maps[0].cells[0][0];
  EXPECT_DOUBLE_EQ(cell.value.value, 1.0);
  EXPECT_EQ(cell.detail, "I 0.2-0.4 s");
  // A window longer than the time before hiding starts at step 0: (9 + 2 + 1)/3 and (9 + 1)/3.
  const std::vector<Heatmap> wide = sensitivityMaps(a, *heatmapMetric(a, {"", 5.0}));
  EXPECT_DOUBLE_EQ(wide[0].cells[0][0]->value.value, (12.0 / 3 + 10.0 / 3) / 2);
  // Without an occlusion the request names its option.
  a.configs[0].occlusions.clear();
  try {
    heatmapMetric(a, {"", 0.6});
    FAIL() << "expected a ScenarioError";
  } catch (const spec::ScenarioError& e) {
    EXPECT_EQ(e.field(), "--before-hiding");
  }
}

TEST(HeatmapMetric, AnUnknownStateNamesTheOptionAndTheStatesThereAre) {
  const SweepAnalysis a = threeAxisSweep();
  EXPECT_EQ(heatmapMetric(a, {"M0"})->label, "fraction of trials in M0 at L");
  try {
    heatmapMetric(a, {"M9"});
    FAIL() << "expected a ScenarioError";
  } catch (const spec::ScenarioError& e) {
    EXPECT_EQ(e.field(), "--state");
    EXPECT_NE(std::string(e.what()).find("M0, M*, Miss 1, Miss >1, Other"), std::string::npos);
  }
}

TEST(SensitivityMaps, NeedTwoNumericAxes) {
  SweepAnalysis a = threeAxisSweep();
  a.axes[1].values = {"\"near\"", "\"far\""};
  EXPECT_TRUE(sensitivityMaps(a, *heatmapMetric(a)).empty());
  EXPECT_EQ(heatmapMarkdown(a, "study/analysis", "Where it emerges"), "");
}

TEST(HeatmapMarkdown, EmbedsEachMapAndItsTable) {
  const std::string md = heatmapMarkdown(threeAxisSweep(), "study/analysis", "Where it emerges");
  EXPECT_NE(md.find("### Where it emerges\n"), std::string::npos);
  EXPECT_NE(md.find("![Where it emerges — planner.algorithm = sma](study/analysis/"
                    "heatmap_distance_vs_horizon_algorithm-sma.png)"),
            std::string::npos);
  EXPECT_NE(
      md.find("| horizon \\ distance | 20 | 30 |\n|---|---:|---:|\n"
              "| 5 | 1.00 [0.91, 1.00] | — |\n| 1 | 0.00 [0.00, 0.09] | 0.50 [0.35, 0.65] |\n"),
      std::string::npos)
      << md;
}

}  // namespace
}  // namespace canopy::analysis
