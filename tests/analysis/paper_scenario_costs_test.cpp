// Why two of the paper's findings do not reproduce (report.md, "Why some findings do not
// reproduce"): the planner's own NBO cost, evaluated on hand-built joint plans, prefers the
// non-cooperative plan. These tests pin that explanation: if the cost changes so that the
// cooperative plan wins, they fail and the report's text must be revisited.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "agents/occlusion_map.h"
#include "agents/planning/nominal_cost.h"
#include "scenarios/loader.h"

namespace canopy::agents::planning {
namespace {

using scenarios::ScenarioSpec;

// A planning problem on the truth at time t0: every track's mean exact, P = variance · I.
struct Problem {
  std::vector<TargetGaussian> targets;
  std::vector<UavState> uavs;
  OcclusionMap map;
  CostSettings settings;
  PlanningProblem view() const { return {targets, uavs, &map, settings}; }
};

Problem problemAt(const ScenarioSpec& spec, double t0, std::vector<Vec2> uav_positions, int horizon,
                  double variance) {
  Problem p;
  for (const scenarios::TargetSpec& t : spec.targets) {
    TargetGaussian g;
    g.x << t.path.positionAt(t0), t.path.velocityAt(t0);
    g.P = variance * Mat4::Identity();
    p.targets.push_back(g);
  }
  for (std::size_t i = 0; i < spec.uavs.size(); ++i) {
    const scenarios::UavSpec& u = spec.uavs[i];
    UavState s;
    s.position = uav_positions[i];
    s.yaw = u.body.yaw;
    s.yaw_mode = u.body.yaw_mode;
    s.v_max = u.body.v_max;
    s.footprint = u.sensor.footprint;
    s.quality = u.sensor.quality;
    p.uavs.push_back(s);
  }
  p.map = OcclusionMap(spec.trees);  // the a-priori map: the true trees
  PlannerConfig config = spec.planner;
  config.horizon = horizon;
  p.settings = CostSettings::from(config, spec.tracking.sigma_a);
  return p;
}

// Each step, fly at up to v_max toward goal(t) as it is at the end of the step, t = t0 + m·Δ.
template <typename Goal>
Plan pursue(const UavState& uav, double t0, int horizon, double period, Goal goal) {
  Plan plan;
  Vec2 p = uav.position;
  for (int m = 1; m <= horizon; ++m) {
    Vec2 step = goal(t0 + m * period) - p;
    const double reach = uav.v_max * period;
    if (step.norm() > reach) step *= reach / step.norm();
    plan.velocities.push_back(step / period);
    p += step;
  }
  return plan;
}

auto walkOf(const ScenarioSpec& spec, int target) {
  return [&spec, target](double t) { return spec.targets[target].path.positionAt(t); };
}

struct Costs {
  double alone, cooperative;
};

// Resource Allocation at t = 0. Alone (keeps M0): UAV2 follows I; UAV1 alternates between III and
// II, 4 s per leg. Cooperative (M*): UAV1 heads for I, UAV2 for the II–III midpoint, at full speed.
Costs resourceAllocationCosts(int horizon, double variance) {
  const ScenarioSpec spec = scenarios::loadScenario("resource_allocation");
  const Problem problem =
      problemAt(spec, 0.0, {spec.uavs[0].body.start, spec.uavs[1].body.start}, horizon, variance);
  const double period = problem.settings.period;
  const auto I = walkOf(spec, 0), II = walkOf(spec, 1), III = walkOf(spec, 2);
  const Plan follow_I = pursue(problem.uavs[1], 0.0, horizon, period, I);
  const Plan zig_zag = pursue(problem.uavs[0], 0.0, horizon, period, [&](double t) {
    return static_cast<int>(std::floor(t / (4 * period))) % 2 == 0 ? III(t) : II(t);
  });
  const Plan to_I = pursue(problem.uavs[0], 0.0, horizon, period, I);
  const Plan to_middle = pursue(problem.uavs[1], 0.0, horizon, period,
                                [&](double t) { return 0.5 * (II(t) + III(t)); });
  const std::vector<Plan> keep{zig_zag, follow_I}, swap{to_I, to_middle};
  return {nominalCost(problem.view(), keep), nominalCost(problem.view(), swap)};
}

// Joint Effect at t0 = 2 s, just before I passes under the crown (2.2 s – 5.0 s), the UAVs over
// their targets. Alone: UAV1 follows I. Cooperative: UAV1 joins UAV2 over II for the steps while I
// is hidden (t ≤ 4 s), then heads back to I. UAV2 follows II in both.
Costs jointEffectCosts(double variance) {
  const ScenarioSpec spec = scenarios::loadScenario("joint_effect");
  const double t0 = 2.0;
  const auto I = walkOf(spec, 0), II = walkOf(spec, 1);
  const Problem problem = problemAt(spec, t0, {I(t0), II(t0)}, spec.planner.horizon, variance);
  const double period = problem.settings.period;
  const int H = problem.settings.horizon;
  const Plan follow_I = pursue(problem.uavs[0], t0, H, period, I);
  const Plan follow_II = pursue(problem.uavs[1], t0, H, period, II);
  const Plan visit_II =
      pursue(problem.uavs[0], t0, H, period, [&](double t) { return t <= 4.0 ? II(t) : I(t); });
  const std::vector<Plan> alone{follow_I, follow_II}, joint{visit_II, follow_II};
  return {nominalCost(problem.view(), alone), nominalCost(problem.view(), joint)};
}

TEST(PaperScenarioCosts, ResourceAllocationSmallUavCannotCoverIWithinFiveSeconds) {
  // Closed form: I walks east at 1 m/s from (35, −7); UAV1 starts at (0, 0) with v_max 5 m/s and
  // a 12 × 12 m footprint. To hold I it must reach x ≥ 35 + t − 6, i.e. 5 t ≥ 29 + t at best:
  // t ≥ 7.25 s > H·Δ = 5 s, whatever it does.
  const ScenarioSpec spec = scenarios::loadScenario("resource_allocation");
  const double half = 0.5 * spec.uavs[0].sensor.footprint.size.x();
  const double gap = spec.targets[0].path.positionAt(0).x() - spec.uavs[0].body.start.x() - half;
  const double t_min = gap / (spec.uavs[0].body.v_max - spec.targets[0].path.velocityAt(0).x());
  EXPECT_NEAR(t_min, 7.25, 1e-9);
  EXPECT_GT(t_min, spec.planner.horizon * spec.planner.plan_period);
}

TEST(PaperScenarioCosts, ResourceAllocationKeepingM0CostsLessThanTheSwap) {
  for (const int horizon : {5, 10}) {
    for (const double variance : {1.0, 0.05}) {
      const Costs c = resourceAllocationCosts(horizon, variance);
      std::printf("RA H = %2d, P = %.2f I: keep M0 %.1f, swap %.1f\n", horizon, variance, c.alone,
                  c.cooperative);
      EXPECT_LT(c.alone, c.cooperative) << "H = " << horizon << ", P = " << variance << " I";
    }
  }
}

TEST(PaperScenarioCosts, JointEffectStayingOverIHiddenCostsLessThanJoiningOverII) {
  for (const double variance : {1.0, 0.05}) {
    const Costs c = jointEffectCosts(variance);
    std::printf("JE P = %.2f I: stay %.2f, join %.2f\n", variance, c.alone, c.cooperative);
    EXPECT_LT(c.alone, c.cooperative) << "P = " << variance << " I";
  }
}

}  // namespace
}  // namespace canopy::agents::planning
