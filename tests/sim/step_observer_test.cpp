// Every observer of a run sees the same steps, 0..K, once each and in order, each as the record
// of what the simulation held after that tick.
#include "sim/step_observer.h"

#include <gtest/gtest.h>

#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/observer_thread.h"
#include "sim/recorder.h"
#include "sim/run.h"
#include "sim/simulation.h"
#include "sim/summary.h"
#include "spec/loader.h"

namespace canopy::sim {
namespace {
namespace fs = std::filesystem;

struct Probe final : StepObserver {
  std::vector<int> steps;
  std::vector<double> times;
  void onStep(const StepRecord& record) override {
    steps.push_back(record.step);
    times.push_back(record.time);
  }
};

// Keeps a copy of every record it is handed.
struct Copier final : StepObserver {
  std::vector<StepRecord> records;
  void onStep(const StepRecord& record) override { records.push_back(record); }
};

struct Thrower final : StepObserver {
  int at;
  explicit Thrower(int step) : at(step) {}
  void onStep(const StepRecord& record) override {
    if (record.step == at) throw std::runtime_error("observer failed");
  }
};

spec::ScenarioSpec demo() {
  spec::LoadOptions load;
  load.overrides = {"clock.duration=2"};
  return spec::loadScenario("demo", load);
}

TEST(StepObserver, AllObserversSeeStepsZeroToKInOrder) {
  const spec::ScenarioSpec spec = demo();
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

TEST(StepObserver, EveryObserverSeesTheRecordTheSimulationHadAtThatStep) {
  // Trajectory Handover plans (SMA), so records carry plans on epochs. A second simulation of the
  // same spec, ticked by hand, gives the reference through its world's and team's accessors.
  spec::LoadOptions load;
  load.overrides = {"clock.duration=3"};
  const spec::ScenarioSpec spec = spec::loadScenario("trajectory_handover", load);
  Simulation sim(spec);
  Copier first, last;
  SummaryBuilder summary(spec);
  StepObserver* const observers[] = {&first, &summary, &last};
  runToEnd(sim, observers);

  Simulation reference(spec);
  ASSERT_EQ(static_cast<int>(first.records.size()), spec.steps() + 1);
  ASSERT_EQ(last.records.size(), first.records.size());
  for (int k = 0; k <= spec.steps(); ++k) {
    reference.tick();
    const world::WorldSnapshot truth = reference.world().snapshot();
    const StepRecord& seen = first.records[k];
    EXPECT_EQ(seen.step, k);
    EXPECT_EQ(seen.time, truth.time);
    for (std::size_t i = 0; i < spec.uavs.size(); ++i) {
      EXPECT_EQ(seen.uavs[i].position, truth.uavs[i].position) << "step " << k;
      EXPECT_EQ(seen.uavs[i].yaw, truth.uavs[i].yaw);
      EXPECT_EQ(seen.uavs[i].command, reference.world().commandedVelocity(static_cast<int>(i)));
    }
    for (std::size_t t = 0; t < spec.targets.size(); ++t)
      EXPECT_EQ(seen.targets[t].position, truth.targets[t].position);
    EXPECT_EQ(seen.fusion.messages, reference.team().fusion().diagnostics().messages);
    EXPECT_EQ(seen.plan.has_value(), k % reference.stepsPerPlan() == 0);
    // Both observers saw the same record, to the last bit of its line.
    EXPECT_EQ(recordLine(spec.labels, last.records[k]), recordLine(spec.labels, seen));
  }
  EXPECT_EQ(summary.steps(), spec.steps() + 1);
}

TEST(StepObserver, RunScenarioHandsItsStepsToExtraObservers) {
  const spec::ScenarioSpec spec = demo();
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
  const spec::ScenarioSpec spec = demo();
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

// ObserverThread (`run --threads N`, N ≥ 2): observers one step behind on a thread of their own.

TEST(ObserverThread, ObserversBehindSeeTheSameRecordsInTheSameOrder) {
  spec::LoadOptions load;
  load.overrides = {"clock.duration=3"};
  const spec::ScenarioSpec spec = spec::loadScenario("trajectory_handover", load);
  Simulation sim(spec);
  Copier here, behind_first, behind_last;
  ObserverThread behind({&behind_first, &behind_last});
  StepObserver* const observers[] = {&behind, &here};
  runToEnd(sim, observers);
  behind.finish();
  ASSERT_EQ(static_cast<int>(here.records.size()), spec.steps() + 1);
  ASSERT_EQ(behind_first.records.size(), here.records.size());
  ASSERT_EQ(behind_last.records.size(), here.records.size());
  for (std::size_t k = 0; k < here.records.size(); ++k) {
    EXPECT_EQ(behind_first.records[k].step, static_cast<int>(k));
    // The copy handed over is the record of that tick, to the last bit of its line (plans on
    // epochs included), though the simulation had already moved on when it was read.
    const std::string line = recordLine(spec.labels, here.records[k]);
    EXPECT_EQ(recordLine(spec.labels, behind_first.records[k]), line) << "step " << k;
    EXPECT_EQ(recordLine(spec.labels, behind_last.records[k]), line) << "step " << k;
  }
}

// Holds the thread at its first step until open() (a planning step the thread is still writing).
struct Gate final : StepObserver {
  std::mutex mutex;
  std::condition_variable opened;
  bool is_open = false;
  std::vector<int> steps;
  void onStep(const StepRecord& record) override {
    std::unique_lock lock(mutex);
    opened.wait(lock, [&] { return is_open; });
    steps.push_back(record.step);
  }
  void open() {
    {
      const std::lock_guard lock(mutex);
      is_open = true;
    }
    opened.notify_all();
  }
};

TEST(ObserverThread, TheCallerHandsOverAsManyStepsAsSlotsWhileTheThreadIsBusy) {
  Gate gate;
  ObserverThread behind({&gate});
  StepRecord record;
  // Every one of these returns while the thread is held at step 0 (were a slot short, the test
  // would hang here and fail on ctest's timeout).
  for (std::size_t k = 0; k < ObserverThread::kSlots; ++k) {
    record.step = static_cast<int>(k);
    behind.onStep(record);
  }
  gate.open();
  record.step = static_cast<int>(ObserverThread::kSlots);  // waits for a slot, then goes in
  behind.onStep(record);
  behind.finish();
  std::vector<int> expected(ObserverThread::kSlots + 1);
  for (std::size_t k = 0; k < expected.size(); ++k) expected[k] = static_cast<int>(k);
  EXPECT_EQ(gate.steps, expected);
}

TEST(ObserverThread, AFailingObserverStopsTheRunAndNoLaterStepIsObserved) {
  const spec::ScenarioSpec spec = demo();
  Simulation sim(spec);
  Thrower thrower(3);
  Probe after, here;
  ObserverThread behind({&thrower, &after});
  StepObserver* const observers[] = {&behind, &here};
  EXPECT_THROW(runToEnd(sim, observers), std::runtime_error);
  EXPECT_EQ(after.steps, (std::vector<int>{0, 1, 2}));  // step 3 never reached it
  // The caller learns of it when it next hands a step over: it has ticked at most as many steps
  // past the failure as the thread holds slots.
  ASSERT_FALSE(here.steps.empty());
  EXPECT_LE(here.steps.back(), 3 + static_cast<int>(ObserverThread::kSlots));
  EXPECT_GE(here.steps.back(), 3);
  EXPECT_THROW(behind.finish(), std::runtime_error);  // and finish() says so too
}

TEST(ObserverThread, RunScenarioOnTwoThreadsWritesWhatOneThreadWrites) {
  const spec::ScenarioSpec spec = demo();
  std::string record[2];
  for (const int threads : {1, 2}) {
    const fs::path dir =
        fs::temp_directory_path() / ("canopy_observer_thread_" + std::to_string(threads));
    fs::remove_all(dir);
    RunOptions options;
    options.out_dir = dir;
    options.threads = threads;
    const RunResult result = runScenario(spec, options);
    EXPECT_EQ(result.steps, spec.steps() + 1);
    std::ifstream in(dir / "record.jsonl");
    record[threads - 1].assign(std::istreambuf_iterator<char>(in), {});
    fs::remove_all(dir);
  }
  EXPECT_GT(record[0].size(), 1000u);
  EXPECT_TRUE(record[0] == record[1]);
}

TEST(ObserverThread, AFailingRecordOnTwoThreadsLeavesNoResult) {
  const spec::ScenarioSpec spec = demo();
  const fs::path dir = fs::temp_directory_path() / "canopy_observer_thread_throw";
  fs::remove_all(dir);
  Thrower thrower(3);  // on the caller's thread: the run stops while the record is written behind
  RunOptions options;
  options.out_dir = dir;
  options.threads = 2;
  options.observers = {&thrower};
  EXPECT_THROW(runScenario(spec, options), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir / "record.jsonl"));
  EXPECT_FALSE(fs::exists(dir / "summary.json"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace canopy::sim
