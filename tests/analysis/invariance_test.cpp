// The findings do not depend on where the layout lies or on its exact numbers: a scenario
// mirrored or rotated gives the same distribution of end states within sampling error, and one
// with its distances or its walking speeds perturbed by ±10 % still shows the finding.
// Monte Carlo over seeded trials (LABEL monte_carlo: Release only).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "analysis/trial_behaviour.h"
#include "experiments/placement.h"
#include "experiments/sweep.h"
#include "experiments/trial.h"
#include "spec/loader.h"

namespace canopy::analysis {
namespace {

using experiments::Placement;
using spec::ScenarioSpec;

constexpr int kTrials = 20;

// The fraction of kTrials trials (common seeds) whose ownership state at L is `state`.
double fractionAtEnd(ScenarioSpec spec, const std::string& state) {
  int hits = 0;
  for (int i = 0; i < kTrials; ++i) {
    spec.seed = experiments::trialSeed(2027, i);
    const experiments::TrialResult trial = experiments::runTrial(spec, "invariance");
    hits += analyseTrial(trial, spec).states[4] == state;
  }
  return static_cast<double>(hits) / kTrials;
}

// Two proportions of kTrials each agree within sampling error: |p − q| ≤ 3 standard errors of
// the difference under the pooled proportion (a two-sided z-test at about the 0.3 % level),
// with the pooled proportion kept off 0 and 1 by half a trial.
void expectSameProportion(double p, double q, const std::string& what) {
  const double pooled = std::clamp(0.5 * (p + q), 0.5 / kTrials, 1.0 - 0.5 / kTrials);
  const double se = std::sqrt(pooled * (1.0 - pooled) * 2.0 / kTrials);
  std::printf("%s: %.2f vs %.2f (3 SE = %.2f)\n", what.c_str(), p, q, 3 * se);
  EXPECT_LE(std::abs(p - q), 3 * se) << what;
}

ScenarioSpec withHorizon(ScenarioSpec spec, int H) {
  spec.planner.horizon = H;
  return spec;
}

TEST(Invariance, ResourceAllocationMirroredAndRotatedSwapsAsOften) {
  const ScenarioSpec spec = spec::loadScenario("resource_allocation");
  const double base = fractionAtEnd(spec, "M*");
  expectSameProportion(fractionAtEnd(experiments::placed(spec, Placement::mirrorX()), "M*"), base,
                       "RA mirrored");
  expectSameProportion(
      fractionAtEnd(experiments::placed(spec, Placement::rotation(0.5 * std::numbers::pi)), "M*"),
      base, "RA rotated 90°");
}

TEST(Invariance, ResourceAllocationPerturbedByTenPercentStillSwapsOnlyWithLookAhead) {
  const ScenarioSpec spec = spec::loadScenario("resource_allocation");
  for (const double scale : {0.9, 1.1}) {
    for (const bool distances : {true, false}) {
      Placement perturbation;
      (distances ? perturbation.distance_scale : perturbation.speed_scale) = scale;
      const ScenarioSpec perturbed = experiments::placed(spec, perturbation);
      const double h5 = fractionAtEnd(withHorizon(perturbed, 5), "M*");
      const double h1 = fractionAtEnd(withHorizon(perturbed, 1), "M*");
      std::printf("RA %s × %.1f: M* at L %.2f (H = 5) vs %.2f (H = 1)\n",
                  distances ? "distances" : "speeds", scale, h5, h1);
      EXPECT_GE(h5, 0.2) << (distances ? "distances × " : "speeds × ") << scale;
      EXPECT_GT(h5, h1) << (distances ? "distances × " : "speeds × ") << scale;
    }
  }
}

// Mean over kTrials trials of the mean number of footprints on the target of the trial's
// `episode`-th occluded interval while it is hidden.
double hiddenCoverage(ScenarioSpec spec, agents::OcclusionMapMode map, std::size_t episode = 0) {
  spec.planner.occlusion_map = map;
  double sum = 0.0;
  for (int i = 0; i < kTrials; ++i) {
    spec.seed = experiments::trialSeed(2027, i);
    const TrialBehaviour b = analyseTrial(experiments::runTrial(spec, "invariance"), spec);
    const OcclusionEpisode& e = b.occlusions.at(episode);
    double covered = 0.0;
    for (int k = e.hidden.first; k <= e.hidden.last; ++k) covered += b.coverage[e.target][k];
    sum += covered / (e.hidden.last - e.hidden.first + 1);
  }
  return sum / kTrials;
}

TEST(Invariance, JointEffectMirroredAndRotatedStillLeavesTheHiddenTrajectory) {
  const ScenarioSpec spec = spec::loadScenario("joint_effect");
  for (const auto& [name, placement] :
       {std::pair{"mirrored", Placement::mirrorX()},
        std::pair{"rotated 90°", Placement::rotation(0.5 * std::numbers::pi)}}) {
    const ScenarioSpec moved = experiments::placed(spec, placement);
    const double a_priori = hiddenCoverage(moved, agents::OcclusionMapMode::a_priori);
    const double none = hiddenCoverage(moved, agents::OcclusionMapMode::none);
    std::printf("JE %s: coverage of I while hidden %.2f (a-priori) vs %.2f (no map)\n", name,
                a_priori, none);
    EXPECT_LT(a_priori, none - 0.2) << name;  // the unmoved layout: 0.40 vs 0.98 (calibration)
  }
}

// The first step at which the mean over kTrials trials of the footprints on I falls below 0.9,
// in seconds (+∞ if never), with the a-priori map and decisions every `replan_period` s.
double reactionOnset(ScenarioSpec spec, double replan_period) {
  spec.planner.occlusion_map = agents::OcclusionMapMode::a_priori;
  spec.planner.replan_period = replan_period;
  std::vector<double> sum(spec.steps() + 1, 0.0);
  for (int i = 0; i < kTrials; ++i) {
    spec.seed = experiments::trialSeed(2027, i);
    const TrialBehaviour b = analyseTrial(experiments::runTrial(spec, "invariance"), spec);
    for (std::size_t k = 0; k < sum.size(); ++k) sum[k] += b.coverage[0][k];
  }
  for (std::size_t k = 0; k < sum.size(); ++k) {
    if (sum[k] < 0.9 * kTrials) return static_cast<double>(k) * spec.dt;
  }
  return INFINITY;
}

TEST(Invariance, JointEffectMirroredAndRotatedReactsBeforeIHidesWithDecisionsAtEveryStep) {
  // I hides at 2.2 s. Decided at every 0.2 s step, the a-priori map leaves I before that (the
  // unmoved layout: 1.8 s on the calibration's seeds and on reproduce's). Decided every 1 s the
  // onset is printed, not checked: it moves between 1.6 and 2.4 s with the seeds and the
  // placement, as the plan from 1.0 s drifts toward II with I at its footprint's edge.
  const ScenarioSpec spec = spec::loadScenario("joint_effect");
  for (const auto& [name, placement] :
       {std::pair{"mirrored", Placement::mirrorX()},
        std::pair{"rotated 90°", Placement::rotation(0.5 * std::numbers::pi)}}) {
    const ScenarioSpec moved = experiments::placed(spec, placement);
    const double every_step = reactionOnset(moved, 0.2), every_second = reactionOnset(moved, 1.0);
    std::printf("JE %s: a-priori onset %.1f s (decisions every 0.2 s) vs %.1f s (every 1 s)\n",
                name, every_step, every_second);
    EXPECT_LT(every_step, 2.2 - 1e-9) << name;
  }
}

TEST(Invariance, OcclusionSharingMirroredStillSharesTheTree) {
  // The robust halves of the two claims (docs/calibration.md, "Occlusion Sharing: the search"):
  // without a map UAV1 keeps looking at hidden I; with the shared dynamic map UAV2 looks away
  // from hidden III as it does with the a-priori map, and less than with no map.
  const ScenarioSpec mirrored =
      experiments::placed(spec::loadScenario("occlusion_sharing"), Placement::mirrorX());
  using agents::OcclusionMapMode;
  const double first_a_priori = hiddenCoverage(mirrored, OcclusionMapMode::a_priori, 0);
  const double first_none = hiddenCoverage(mirrored, OcclusionMapMode::none, 0);
  const double second_dynamic = hiddenCoverage(mirrored, OcclusionMapMode::dynamic, 1);
  const double second_none = hiddenCoverage(mirrored, OcclusionMapMode::none, 1);
  std::printf(
      "OS mirrored: I while hidden %.2f (a-priori) vs %.2f (none); III %.2f (dynamic) "
      "vs %.2f (none)\n",
      first_a_priori, first_none, second_dynamic, second_none);
  EXPECT_LT(first_a_priori, first_none - 0.2);   // unmoved, 40 trials: 0.59 vs 0.97
  EXPECT_LT(second_dynamic, second_none - 0.1);  // unmoved, 40 trials: 0.43 vs 0.74
}

TEST(Invariance, TrajectoryHandoverMirroredEndsInTheZoneDefenceAsOften) {
  const ScenarioSpec spec = spec::loadScenario("trajectory_handover");
  expectSameProportion(fractionAtEnd(experiments::placed(spec, Placement::mirrorX()), "M*"),
                       fractionAtEnd(spec, "M*"), "TH mirrored");
}

}  // namespace
}  // namespace canopy::analysis
