// The step record against what the simulation's world and team hold after the same tick, and
// against closed forms: footprints placed at the pose, footprint membership and canopy
// visibility recomputed from the truth, planned paths integrated from the plan.
#include "sim/step_record.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "sim/simulation.h"
#include "spec/loader.h"

namespace canopy::sim {
namespace {

// Occlusion Sharing plans (SMA, dynamic occlusion maps) and hides its target I under a tree.
spec::ScenarioSpec occlusionSharing() {
  spec::LoadOptions load;
  load.overrides = {"clock.duration=10"};
  return spec::loadScenario("occlusion_sharing", load);
}

void expectFootprintEq(const sensing::Footprint& a, const sensing::Footprint& b) {
  EXPECT_EQ(a.shape, b.shape);
  EXPECT_EQ(a.centre, b.centre);
  EXPECT_EQ(a.cos_yaw, b.cos_yaw);
  EXPECT_EQ(a.sin_yaw, b.sin_yaw);
  EXPECT_EQ(a.half, b.half);
  EXPECT_EQ(a.radius, b.radius);
}

template <int N>
void expectGaussianEq(const agents::Gaussian<N>& a, const agents::Gaussian<N>& b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.P, b.P);
}

TEST(StepRecord, HoldsWhatTheWorldAndTheTeamHoldAfterTheTick) {
  const spec::ScenarioSpec spec = occlusionSharing();
  ASSERT_EQ(spec.sensing.occlusion_model, sensing::OcclusionModel::canopy);
  Simulation sim(spec);
  int occluded_steps = 0, epochs = 0;
  while (!sim.done()) {
    const StepRecord& record = sim.tick();
    EXPECT_EQ(&record, &sim.lastStep());
    const world::WorldSnapshot truth = sim.world().snapshot();
    ASSERT_EQ(record.step, truth.step);
    EXPECT_EQ(record.time, truth.time);
    ASSERT_EQ(record.uavs.size(), spec.uavs.size());
    ASSERT_EQ(record.targets.size(), spec.targets.size());

    std::vector<int> occluded;
    for (std::size_t t = 0; t < record.targets.size(); ++t) {
      const TargetRecord& target = record.targets[t];
      EXPECT_EQ(target.position, truth.targets[t].position);
      EXPECT_EQ(target.velocity, truth.targets[t].velocity);
      EXPECT_EQ(target.occluded, sim.world().insideOccluder(target.position));
      if (target.occluded) occluded.push_back(static_cast<int>(t));
    }
    occluded_steps += !occluded.empty();

    for (std::size_t i = 0; i < record.uavs.size(); ++i) {
      const UavRecord& uav = record.uavs[i];
      EXPECT_EQ(uav.position, truth.uavs[i].position);
      EXPECT_EQ(uav.yaw, truth.uavs[i].yaw);
      EXPECT_EQ(uav.velocity, truth.uavs[i].velocity);
      EXPECT_EQ(uav.command, sim.world().commandedVelocity(static_cast<int>(i)));
      expectFootprintEq(uav.footprint, sensing::Footprint::place(spec.uavs[i].sensor.footprint,
                                                                 uav.position, uav.yaw));
      // Membership and canopy visibility (paper eq. 3) from the truth alone.
      std::vector<int> inside, visible;
      for (std::size_t t = 0; t < record.targets.size(); ++t) {
        if (!uav.footprint.contains(record.targets[t].position)) continue;
        inside.push_back(static_cast<int>(t));
        if (!record.targets[t].occluded) visible.push_back(static_cast<int>(t));
      }
      EXPECT_EQ(uav.scan.uav, static_cast<int>(i));
      EXPECT_EQ(uav.scan.sensor_position, uav.position);
      EXPECT_EQ(uav.scan.in_footprint, inside);
      EXPECT_EQ(uav.scan.visible, visible);
    }

    const std::vector<agents::Agent>& agents = sim.team().agents();
    ASSERT_EQ(record.beliefs.size(), agents.size());
    ASSERT_EQ(record.counts.size(), agents.size());
    for (std::size_t i = 0; i < agents.size(); ++i) {
      const agents::tracking::Tracker& tracker = agents[i].tracker();
      std::vector<const agents::tracking::TargetTrack*> confirmed;
      for (const auto& track : tracker.targets()) {
        if (track.status == agents::tracking::TrackStatus::confirmed) confirmed.push_back(&track);
      }
      const agents::AgentBelief& belief = record.beliefs[i];
      ASSERT_EQ(belief.tracks.size(), confirmed.size());
      for (std::size_t j = 0; j < confirmed.size(); ++j) {
        EXPECT_EQ(belief.tracks[j].key, confirmed[j]->key);
        EXPECT_EQ(belief.tracks[j].label, confirmed[j]->label);
        expectGaussianEq(belief.tracks[j].belief, confirmed[j]->posterior);
      }
      std::vector<const agents::tracking::TreeTrack*> trees;
      for (const auto& tree : tracker.trees()) {
        if (tree.status == agents::tracking::TrackStatus::confirmed) trees.push_back(&tree);
      }
      ASSERT_EQ(belief.trees.size(), trees.size());
      for (std::size_t j = 0; j < trees.size(); ++j) {
        EXPECT_EQ(belief.trees[j].key, trees[j]->key);
        expectGaussianEq(belief.trees[j].belief, trees[j]->posterior);
      }
      EXPECT_EQ(record.counts[i].tracks, tracker.targets().size());
      EXPECT_EQ(record.counts[i].trees_in_map, agents[i].map().trees().size());
      EXPECT_EQ(record.counts[i].tracking.births, tracker.diagnostics().births);
      EXPECT_EQ(record.counts[i].tracking.deletions, tracker.diagnostics().deletions);
    }
    EXPECT_EQ(record.fusion.steps, record.step + 1);  // one fusion per step
    EXPECT_EQ(record.fusion.messages, sim.team().fusion().diagnostics().messages);
    EXPECT_EQ(record.fusion.adoptions, sim.team().fusion().diagnostics().adoptions);

    const bool epoch = record.step % sim.stepsPerPlan() == 0;
    ASSERT_EQ(record.plan.has_value(), epoch) << "step " << record.step;
    if (!epoch) continue;
    ++epochs;
    EXPECT_EQ(record.plan->epoch, record.step / sim.stepsPerPlan());
    for (std::size_t i = 0; i < record.uavs.size(); ++i) {
      // p_{i,m} = p_{i,m−1} + a_{i,m}·Δ from the UAV's position, each action clamped to v_max.
      const double v_max = spec.uavs[i].body.v_max;
      Vec2 p = record.uavs[i].position;
      const std::vector<Vec2>& path = record.beliefs[i].planned_path;
      const std::vector<Vec2>& actions = record.plan->plans[i].velocities;
      ASSERT_EQ(path.size(), actions.size());
      for (std::size_t m = 0; m < actions.size(); ++m) {
        const Vec2 a =
            actions[m].norm() > v_max ? Vec2(actions[m] * (v_max / actions[m].norm())) : actions[m];
        p += a * spec.planner.plan_period;
        EXPECT_NEAR((path[m] - p).norm(), 0.0, 1e-12);
      }
      // The first action is what the UAV was commanded, within v_max.
      const Vec2 first = actions.front();
      const Vec2 clamped = first.norm() > v_max ? Vec2(first * (v_max / first.norm())) : first;
      EXPECT_NEAR((record.uavs[i].command - clamped).norm(), 0.0, 1e-12);
    }
  }
  EXPECT_GT(occluded_steps, 0);  // the test saw an occlusion
  EXPECT_GT(epochs, 5);
}

TEST(StepRecord, TruthSnapshotIsTheWorldsSnapshot) {
  Simulation sim(occlusionSharing());
  world::WorldSnapshot converted;
  for (int k = 0; k < 12; ++k) {
    truthSnapshot(sim.tick(), converted);
    const world::WorldSnapshot truth = sim.world().snapshot();
    EXPECT_EQ(converted.step, truth.step);
    EXPECT_EQ(converted.time, truth.time);
    ASSERT_EQ(converted.uavs.size(), truth.uavs.size());
    for (std::size_t i = 0; i < truth.uavs.size(); ++i) {
      EXPECT_EQ(converted.uavs[i].position, truth.uavs[i].position);
      EXPECT_EQ(converted.uavs[i].velocity, truth.uavs[i].velocity);
      EXPECT_EQ(converted.uavs[i].yaw, truth.uavs[i].yaw);
    }
    ASSERT_EQ(converted.targets.size(), truth.targets.size());
    for (std::size_t t = 0; t < truth.targets.size(); ++t) {
      EXPECT_EQ(converted.targets[t].position, truth.targets[t].position);
      EXPECT_EQ(converted.targets[t].velocity, truth.targets[t].velocity);
    }
  }
}

}  // namespace
}  // namespace canopy::sim
