// Simulation: its own spec, and the external-command hook against closed forms.
#include "sim/simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "spec/loader.h"

namespace canopy::sim {
namespace {

spec::ScenarioSpec shortRun(const char* name, double duration = 2.0) {
  spec::LoadOptions load;
  load.overrides = {"clock.duration=" + std::to_string(duration)};
  return spec::loadScenario(name, load);
}

// Box2D keeps positions in float: metres to about 1e-5 over a few steps.
constexpr double kFloatMetres = 1e-4;

TEST(Simulation, BuiltFromATemporarySpecOwnsIt) {
  // The spec is a temporary that is gone before the first tick (ASan would see a dangling read).
  Simulation sim(spec::loadScenario("demo"));
  int steps = 0;
  while (!sim.done()) {
    sim.tick();
    ++steps;
  }
  EXPECT_EQ(steps, sim.spec().steps() + 1);
  EXPECT_EQ(sim.spec().name, "demo");
}

TEST(Simulation, KeepsItsCopyWhenTheCallersSpecChanges) {
  spec::ScenarioSpec spec = shortRun("demo");
  Simulation sim(spec);
  const double dt = spec.dt;
  spec.dt = 99.0;
  spec.name = "changed";
  EXPECT_EQ(sim.spec().dt, dt);
  EXPECT_EQ(sim.spec().name, "demo");
}

TEST(Simulation, ExternalCommandMovesTheUavAlongItForOneStep) {
  Simulation sim(shortRun("demo"));
  const Vec2 p0 = sim.tick().uavs[0].position;
  const Vec2 v(1.25, -2.5);  // |v| = 2.80 m/s < v_max = 5 m/s
  sim.commandNext(0, v);
  EXPECT_EQ(sim.world().commandedVelocity(0), v);
  const StepRecord& step = sim.tick();
  const double dt = sim.spec().dt;
  EXPECT_EQ(step.uavs[0].velocity, v);  // the velocity flown over the step
  EXPECT_NEAR(step.uavs[0].position.x(), p0.x() + v.x() * dt, kFloatMetres);
  EXPECT_NEAR(step.uavs[0].position.y(), p0.y() + v.y() * dt, kFloatMetres);
  // The next step is the script's again: aim at the path's position one step ahead.
  const Vec2 p1 = step.uavs[0].position;
  const Vec2 aim = (sim.spec().uavs[0].path->positionAt(step.time + dt) - p1) / dt;
  const double v_max = sim.spec().uavs[0].body.v_max;
  const Vec2 scripted = aim.norm() > v_max ? Vec2(aim * (v_max / aim.norm())) : aim;
  EXPECT_EQ(sim.world().commandedVelocity(0), scripted);
}

TEST(Simulation, ExternalCommandIsClampedToVmax) {
  Simulation sim(shortRun("demo"));
  const Vec2 p0 = sim.tick().uavs[0].position;
  const double v_max = sim.spec().uavs[0].body.v_max;  // 5 m/s
  const Vec2 direction = Vec2(3.0, 4.0) / 5.0;
  sim.commandNext(0, 10.0 * v_max * direction);
  const StepRecord& step = sim.tick();
  const double dt = sim.spec().dt;
  EXPECT_NEAR(step.uavs[0].velocity.norm(), v_max, 1e-12);
  EXPECT_NEAR(step.uavs[0].position.x(), p0.x() + v_max * direction.x() * dt, kFloatMetres);
  EXPECT_NEAR(step.uavs[0].position.y(), p0.y() + v_max * direction.y() * dt, kFloatMetres);
}

TEST(Simulation, ExternalCommandLeavesOtherUavsAndPlanningEpochsAlone) {
  // Trajectory Handover plans with SMA every plan_period; UAV 0 is steered externally at every
  // step, UAV 1 is not commanded.
  Simulation steered(shortRun("trajectory_handover", 3.0));
  Simulation free(shortRun("trajectory_handover", 3.0));
  steered.tick();
  free.tick();
  const Vec2 v(0.0, 1.0);
  int epochs = 0;
  while (!steered.done()) {
    steered.commandNext(0, v);
    const StepRecord& step = steered.tick();
    const StepRecord& free_step = free.tick();
    EXPECT_EQ(step.uavs[0].velocity, v);
    const bool epoch = step.step % steered.stepsPerPlan() == 0;
    EXPECT_EQ(step.plan.has_value(), epoch) << "step " << step.step;
    EXPECT_EQ(free_step.plan.has_value(), epoch);
    epochs += epoch;
    if (step.plan) {
      // The planner still commands UAV 0 (its plan is recorded), the hook overrides it after.
      EXPECT_EQ(steered.world().commandedVelocity(1), step.plan->plans[1].command());
    }
  }
  EXPECT_GT(epochs, 2);
  // Without the hook, UAV 0 flies its plans, not v.
  EXPECT_NE(free.lastStep().uavs[0].velocity, v);
}

TEST(Simulation, ReplanPeriodDefaultsToThePlanPeriodAndSetsTheEpochs) {
  EXPECT_EQ(shortRun("trajectory_handover").planner.replan_period, 1.0);
  spec::LoadOptions load;
  load.overrides = {"clock.duration=1.0", "planner.replan_period=0.2"};
  Simulation sim(spec::loadScenario("trajectory_handover", load));
  EXPECT_EQ(sim.stepsPerPlan(), 1);
  int epoch = 0;
  while (!sim.done()) {
    const StepRecord& step = sim.tick();
    ASSERT_TRUE(step.plan.has_value()) << "step " << step.step;
    EXPECT_EQ(step.plan->epoch, epoch++);  // one epoch per 0.2 s step
  }
  EXPECT_EQ(epoch, 6);
}

TEST(Simulation, ExternalCommandRefusedOutsideTheRun) {
  Simulation sim(shortRun("demo", 0.4));
  EXPECT_THROW(sim.commandNext(0, Vec2::Zero()), std::logic_error);  // before the first tick
  sim.tick();
  EXPECT_THROW(sim.commandNext(2, Vec2::Zero()), std::out_of_range);
  EXPECT_THROW(sim.commandNext(-1, Vec2::Zero()), std::out_of_range);
  EXPECT_THROW(sim.commandNext(0, Vec2(std::numeric_limits<double>::quiet_NaN(), 0.0)),
               std::invalid_argument);
  while (!sim.done()) sim.tick();
  EXPECT_THROW(sim.commandNext(0, Vec2::Zero()), std::logic_error);  // no next step
}

}  // namespace
}  // namespace canopy::sim
