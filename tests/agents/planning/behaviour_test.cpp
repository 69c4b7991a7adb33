// Closed-loop behaviour of the planner: targets at constant velocity, a belief that follows the
// truth with a fixed covariance, UAV positions integrated by the applied command (one epoch per
// plan_period).
#include <gtest/gtest.h>

#include <vector>

#include "agents/planning/team_planner.h"
#include "sensing/footprint.h"

namespace canopy::agents::planning {
namespace {

struct Truth {
  Vec2 position;  // m
  Vec2 velocity;  // m/s
};

class ClosedLoop {
 public:
  ClosedLoop(const PlannerConfig& config, std::vector<UavState> uavs, std::vector<Truth> targets,
             const OcclusionMap* map, std::uint64_t seed)
      : config_(config),
        uavs_(std::move(uavs)),
        targets_(std::move(targets)),
        map_(map),
        planner_(config, 1.0, seed) {}

  // Plans, applies the commands for one plan_period and moves the targets.
  void epoch() {
    std::vector<TargetGaussian> belief;
    for (const Truth& t : targets_) {
      TargetGaussian g;
      g.x << t.position, t.velocity;
      g.P = Mat4::Identity();  // fixed covariance
      belief.push_back(g);
    }
    const std::vector<AgentView> views(uavs_.size(), AgentView{belief, map_});
    const TeamPlan plan = planner_.plan(epoch_++, uavs_, views);
    const double dt = config_.plan_period;
    for (std::size_t i = 0; i < uavs_.size(); ++i) {
      uavs_[i].position += plan.plans[i].command() * dt;
    }
    for (Truth& t : targets_) t.position += t.velocity * dt;
  }
  bool covers(int uav, int target) const {
    const UavState& u = uavs_[uav];
    return sensing::Footprint::place(u.footprint, u.position, u.yaw)
        .contains(targets_[target].position);
  }
  const UavState& uav(int i) const { return uavs_[i]; }
  const Truth& target(int j) const { return targets_[j]; }

 private:
  PlannerConfig config_;
  std::vector<UavState> uavs_;
  std::vector<Truth> targets_;
  const OcclusionMap* map_;
  TeamPlanner planner_;
  int epoch_ = 0;
};

PlannerConfig smaConfig(int horizon) {
  PlannerConfig c;
  c.algorithm = PlannerAlgorithm::sma;
  c.horizon = horizon;
  return c;
}

TEST(PlannerBehaviour, LoneUavMovesTowardAnUncoveredTarget) {
  for (const int horizon : {1, 5}) {
    ClosedLoop loop(smaConfig(horizon), {UavState{}}, {{Vec2(40, 10), Vec2(0.5, 0)}}, nullptr, 1);
    double distance = (loop.target(0).position - loop.uav(0).position).norm();
    for (int k = 0; k < 4; ++k) {  // 4 s at 5 m/s close 20 m of the 40
      loop.epoch();
      const double now = (loop.target(0).position - loop.uav(0).position).norm();
      EXPECT_LT(now, distance - 3.0) << "H = " << horizon << ", epoch " << k;
      distance = now;
    }
    for (int k = 0; k < 4; ++k) loop.epoch();
    EXPECT_TRUE(loop.covers(0, 0)) << "H = " << horizon;
  }
}

// Target A (0, 0) → east at 2 m/s passes under a crown of radius 12 m at (14, 0) from t = 1 s to
// t = 13 s. Target B runs parallel 60 m north: out of reach within the horizon from over A.
// With the a-priori map the UAV knows A will be hidden and leaves for B; with no map it keeps A
// in its footprint (leaving would lose A for a B it cannot reach within H).
TEST(PlannerBehaviour, UavLeavesATargetAboutToBeOccludedOnlyWhenItsMapShowsTheTree) {
  const OcclusionMap a_priori({world::TreeDef::disc({14, 0}, 12)});
  const std::vector<Truth> targets{{Vec2(0, 0), Vec2(2, 0)}, {Vec2(0, 60), Vec2(2, 0)}};
  for (const std::uint64_t seed : {1, 2}) {
    ClosedLoop aware(smaConfig(5), {UavState{}}, targets, &a_priori, seed);
    ClosedLoop unaware(smaConfig(5), {UavState{}}, targets, nullptr, seed);
    for (int k = 1; k <= 12; ++k) {
      aware.epoch();
      unaware.epoch();
      EXPECT_TRUE(unaware.covers(0, 0)) << "no map, t = " << k << " s, seed " << seed;
      EXPECT_FALSE(unaware.covers(0, 1)) << "no map, t = " << k << " s, seed " << seed;
    }
    EXPECT_GT(aware.uav(0).position.y(), 40.0) << "seed " << seed;
    EXPECT_TRUE(aware.covers(0, 1)) << "a-priori map, seed " << seed;
    EXPECT_FALSE(aware.covers(0, 0)) << "a-priori map, seed " << seed;
  }
}

}  // namespace
}  // namespace canopy::agents::planning
