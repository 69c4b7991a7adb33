// Every observer of a run sees the same steps, 0..K, once each and in order.
#include "scenarios/step_observer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <vector>

#include "scenarios/loader.h"
#include "scenarios/run.h"
#include "scenarios/summary.h"

namespace canopy::scenarios {
namespace {
namespace fs = std::filesystem;

struct Probe final : StepObserver {
  std::vector<int> steps;
  std::vector<double> times;
  void onStep(const Simulation& sim) override {
    steps.push_back(sim.truth().step);
    times.push_back(sim.truth().time);
  }
};

struct Thrower final : StepObserver {
  int at;
  explicit Thrower(int step) : at(step) {}
  void onStep(const Simulation& sim) override {
    if (sim.truth().step == at) throw std::runtime_error("observer failed");
  }
};

ScenarioSpec demo() {
  LoadOptions load;
  load.overrides = {"clock.duration=2"};
  return loadScenario("demo", load);
}

TEST(StepObserver, AllObserversSeeStepsZeroToKInOrder) {
  const ScenarioSpec spec = demo();
  Simulation sim(spec);
  Probe a, b;
  SummaryBuilder summary(spec);
  StepObserver* const observers[] = {&a, &summary, &b};
  runToEnd(sim, observers);
  std::vector<int> expected;
  for (int k = 0; k <= spec.steps(); ++k) expected.push_back(k);
  EXPECT_EQ(a.steps, expected);
  EXPECT_EQ(b.steps, expected);
  EXPECT_EQ(a.times, b.times);
  EXPECT_EQ(summary.steps(), spec.steps() + 1);
  EXPECT_NEAR(a.times.back(), spec.steps() * spec.dt, 1e-9);  // t accumulates dt
}

TEST(StepObserver, RunScenarioHandsItsStepsToExtraObservers) {
  const ScenarioSpec spec = demo();
  const fs::path dir = fs::temp_directory_path() / "canopy_observer_run";
  fs::remove_all(dir);
  Probe probe;
  RunOptions options;
  options.out_dir = dir;
  options.observers = {&probe};
  const RunResult result = runScenario(spec, options);
  EXPECT_EQ(static_cast<int>(probe.steps.size()), result.steps);
  EXPECT_EQ(probe.steps.front(), 0);
  EXPECT_EQ(probe.steps.back(), spec.steps());
  fs::remove_all(dir);
}

TEST(StepObserver, AFailingObserverStopsTheRunAndLeavesNoResult) {
  const ScenarioSpec spec = demo();
  const fs::path dir = fs::temp_directory_path() / "canopy_observer_throw";
  fs::remove_all(dir);
  Thrower thrower(3);
  Probe after;
  RunOptions options;
  options.out_dir = dir;
  options.observers = {&thrower, &after};
  EXPECT_THROW(runScenario(spec, options), std::runtime_error);
  EXPECT_EQ(after.steps, (std::vector<int>{0, 1, 2}));  // step 3 never reached it
  EXPECT_FALSE(fs::exists(dir / "record.jsonl"));
  EXPECT_FALSE(fs::exists(dir / "summary.json"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace canopy::scenarios
