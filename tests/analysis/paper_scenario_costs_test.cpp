// Why two of the paper's findings did not reproduce under the first reconstruction
// (resource_allocation_v1; report.md, "Why some findings do not reproduce"): the planner's own NBO
// cost, evaluated on hand-built joint plans, does not reward the cooperative plan. In Resource
// Allocation keeping M0 is far cheaper than the swap; in Joint Effect joining II while I is hidden
// gains less than the swarm's stall tolerance. Both hold for the position trace (our default) and
// the full trace of P (the paper's eq. 5), with and without the terminal penalty. If the cost
// changes so that the cooperative plan wins, these tests fail and the report's text must be
// revisited.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "agents/occlusion_map.h"
#include "agents/planning/nominal_cost.h"
#include "sim/simulation.h"
#include "spec/loader.h"

namespace canopy::agents::planning {
namespace {

using spec::ScenarioSpec;

// A planning problem on the truth at time t0: every track's mean exact, P = variance · I.
struct Problem {
  std::vector<TargetGaussian> targets;
  std::vector<UavState> uavs;
  OcclusionMap map;
  CostSettings settings;
  PlanningProblem view() const { return {targets, uavs, &map, settings}; }
};

// The cost's variants the explanation is checked under.
struct CostVariant {
  bool full_trace = false;
  bool terminal_penalty = true;
};
const CostVariant kVariants[] = {{false, true}, {true, true}, {false, false}, {true, false}};

std::string describe(const CostVariant& v) {
  return std::string(v.full_trace ? "tr P" : "tr P_pos") +
         (v.terminal_penalty ? ", terminal penalty" : ", no terminal penalty");
}

Problem problemAt(const ScenarioSpec& spec, double t0, const std::vector<Vec2>& uav_positions,
                  int horizon, double variance, const CostVariant& variant) {
  Problem p;
  for (const spec::TargetSpec& t : spec.targets) {
    TargetGaussian g;
    g.x << t.path.positionAt(t0), t.path.velocityAt(t0);
    g.P = variance * Mat4::Identity();
    p.targets.push_back(g);
  }
  p.uavs = sim::teamConfig(spec).uavs;
  for (std::size_t i = 0; i < p.uavs.size(); ++i) p.uavs[i].position = uav_positions[i];
  p.map = OcclusionMap(spec.trees);  // the a-priori map: the true trees
  PlannerConfig config = spec.planner;
  config.horizon = horizon;
  config.full_trace = variant.full_trace;
  config.terminal_penalty = variant.terminal_penalty;
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
  return [&spec, target](double t) -> Vec2 { return spec.targets[target].path.positionAt(t); };
}

struct Costs {
  double alone, cooperative;
};

// Resource Allocation at t = 0. Alone (keeps M0): UAV2 follows I; UAV1 alternates between III and
// II, 4 s per leg. Cooperative (M*): UAV1 heads for I, UAV2 for the II–III midpoint, at full speed.
Costs resourceAllocationCosts(const ScenarioSpec& spec, int horizon, double variance,
                              const CostVariant& variant) {
  const Problem problem = problemAt(spec, 0.0, {spec.uavs[0].body.start, spec.uavs[1].body.start},
                                    horizon, variance, variant);
  const double period = problem.settings.period;
  const auto I = walkOf(spec, 0), II = walkOf(spec, 1), III = walkOf(spec, 2);
  const Plan follow_I = pursue(problem.uavs[1], 0.0, horizon, period, I);
  const Plan zig_zag = pursue(problem.uavs[0], 0.0, horizon, period, [&](double t) -> Vec2 {
    return static_cast<int>(std::floor(t / (4 * period))) % 2 == 0 ? III(t) : II(t);
  });
  const Plan to_I = pursue(problem.uavs[0], 0.0, horizon, period, I);
  const Plan to_middle = pursue(problem.uavs[1], 0.0, horizon, period,
                                [&](double t) -> Vec2 { return 0.5 * (II(t) + III(t)); });
  const std::vector<Plan> keep{zig_zag, follow_I}, swap{to_I, to_middle};
  return {nominalCost(problem.view(), keep), nominalCost(problem.view(), swap)};
}

// Joint Effect at a planning epoch t0 before or as I passes under the crown (2.2 s – 5.0 s), the
// UAVs over their targets, the a-priori map. Alone: UAV1 follows I, UAV2 follows II. Cooperative:
// the cheapest of a family of plans in which UAV1 leaves I at step a, flies to a point on II's
// side (over II, halfway, or with II 0.5 m inside its footprint's edge) and stays there
// (moving east with the walkers) until step b, then heads back to I; UAV2 follows II throughout.
// leave_at: only plans leaving at that step a (0: any).
Costs jointEffectCosts(const ScenarioSpec& spec, double t0, double variance,
                       const CostVariant& variant, int leave_at = 0) {
  const auto I = walkOf(spec, 0), II = walkOf(spec, 1);
  const Problem problem =
      problemAt(spec, t0, {I(t0), II(t0)}, spec.planner.horizon, variance, variant);
  const double period = problem.settings.period;
  const int H = problem.settings.horizon;
  const Plan follow_I = pursue(problem.uavs[0], t0, H, period, I);
  const Plan follow_II = pursue(problem.uavs[1], t0, H, period, II);
  const std::vector<Plan> alone{follow_I, follow_II};
  const double half = 0.5 * spec.uavs[0].sensor.footprint.size.y();
  const double y_II = II(t0).y();
  double best_join = std::numeric_limits<double>::infinity();
  for (const double y : {y_II, y_II + 0.5 * (half - 0.5), y_II + half - 0.5}) {
    for (int a = leave_at > 0 ? leave_at : 1; a <= (leave_at > 0 ? leave_at : H); ++a) {
      for (int b = a + 1; b <= H + 1; ++b) {  // b = H + 1: never back within the horizon
        const Plan join = pursue(problem.uavs[0], t0, H, period, [&](double t) -> Vec2 {
          const double m = (t - t0) / period;
          return m >= a && m < b ? Vec2(I(t).x(), y) : I(t);
        });
        const std::vector<Plan> joint{join, follow_II};
        best_join = std::min(best_join, nominalCost(problem.view(), joint));
      }
    }
  }
  return {nominalCost(problem.view(), alone), best_join};
}

TEST(PaperScenarioCosts, ResourceAllocationSmallUavCannotCoverIWithinFiveSeconds) {
  // Closed form: I walks east at 1 m/s from (35, −7); UAV1 starts at (0, 0) with v_max 5 m/s and
  // a 12 × 12 m footprint. To hold I it must reach x ≥ 35 + t − 6, i.e. 5 t ≥ 29 + t at best:
  // t ≥ 7.25 s > H·Δ = 5 s, whatever it does.
  const ScenarioSpec spec = spec::loadScenario("resource_allocation_v1");
  const double half = 0.5 * spec.uavs[0].sensor.footprint.size.x();
  const double gap = spec.targets[0].path.positionAt(0).x() - spec.uavs[0].body.start.x() - half;
  const double t_min = gap / (spec.uavs[0].body.v_max - spec.targets[0].path.velocityAt(0).x());
  EXPECT_NEAR(t_min, 7.25, 1e-9);
  EXPECT_GT(t_min, spec.planner.horizon * spec.planner.plan_period);
}

TEST(PaperScenarioCosts, ResourceAllocationKeepingM0CostsLessThanTheSwap) {
  const ScenarioSpec spec = spec::loadScenario("resource_allocation_v1");
  for (const CostVariant& variant : kVariants) {
    for (const int horizon : {5, 10}) {
      for (const double variance : {1.0, 0.05}) {
        const Costs c = resourceAllocationCosts(spec, horizon, variance, variant);
        std::printf("RA %s, H = %2d, P = %.2f I: keep M0 %.1f, swap %.1f\n",
                    describe(variant).c_str(), horizon, variance, c.alone, c.cooperative);
        EXPECT_LT(c.alone, c.cooperative)
            << describe(variant) << ", H = " << horizon << ", P = " << variance << " I";
      }
    }
  }
}

TEST(PaperScenarioCosts, JointEffectJoiningIIWhileIIsHiddenGainsLessThanTheSwarmTolerance) {
  // The swarm counts an iteration as stalled when the best cost moves by less than
  // ftol·(1 + |J|): a gain below that does not keep it searching, and its warm start follows I.
  const ScenarioSpec spec = spec::loadScenario("joint_effect_v1");
  const double ftol = spec.planner.pso.ftol;
  for (const CostVariant& variant : kVariants) {
    for (const double t0 : {1.0, 2.0}) {
      for (const double variance : {1.0, 0.05}) {
        const Costs c = jointEffectCosts(spec, t0, variance, variant);
        std::printf("JE %s, t0 = %.0f s, P = %.2f I: stay %.4f, cheapest join %.4f\n",
                    describe(variant).c_str(), t0, variance, c.alone, c.cooperative);
        EXPECT_LT(std::abs(c.alone - c.cooperative), ftol * (1.0 + std::abs(c.alone)))
            << describe(variant) << ", t0 = " << t0 << " s, P = " << variance << " I";
      }
    }
  }
}

TEST(PaperScenarioCosts, CalibratedJointEffectPaysForJoiningButOnlyFromThePlanInstantBeforeIHides) {
  // The calibrated layout (tracks 8 m apart): at t0 = 1 s joining II beats following I by more
  // than the swarm's tolerance, but the cheapest plans leave I in the action from 2 s (a = 2),
  // the last plan instant before I hides at 2.2 s; leaving in the action from 1 s (a = 1) costs
  // more (with the position trace, more than staying). So the cost does not reward leaving
  // before 2.0 s (report.md's reaction table; the paper: about 1.6 s).
  const ScenarioSpec spec = spec::loadScenario("joint_effect");
  const double ftol = spec.planner.pso.ftol;
  for (const CostVariant& variant : kVariants) {
    for (const double variance : {1.0, 0.05}) {
      const Costs any = jointEffectCosts(spec, 1.0, variance, variant);
      const Costs early = jointEffectCosts(spec, 1.0, variance, variant, 1);
      const Costs at_two = jointEffectCosts(spec, 1.0, variance, variant, 2);
      std::printf("JE calibrated %s, P = %.2f I: stay %.4f, join from 1 s %.4f, from 2 s %.4f\n",
                  describe(variant).c_str(), variance, any.alone, early.cooperative,
                  at_two.cooperative);
      EXPECT_LT(any.cooperative, any.alone - ftol * (1.0 + any.alone)) << describe(variant);
      EXPECT_EQ(any.cooperative, at_two.cooperative) << describe(variant);
      EXPECT_GT(early.cooperative, at_two.cooperative) << describe(variant);
    }
  }
}

TEST(PaperScenarioCosts, CalibratedJointEffectDecidedInsideAnActionLeavesIAtOnce) {
  // With decisions at every 0.2 s step (planner.replan_period), a plan made at t0 = 1.4 s looks
  // at 2.4 s, 3.4 s, 4.4 s — I hidden at each — and 5.4 s: joining II in the very first action
  // beats following I by more than the swarm's tolerance, so UAV1 leaves 0.8 s before I hides;
  // at t0 = 1.0 s the first sample (2.0 s) still sees I and leaving at once costs more than
  // staying (the test above). A departure decided before I hides needs a decision between 1.2 s
  // and 2.2 s; with decisions every 1 s the plan from 1.0 s can only drift toward II while
  // keeping I in view at 2.0 s (docs/calibration.md, "Joint Effect: the second search").
  const ScenarioSpec spec = spec::loadScenario("joint_effect");
  const double ftol = spec.planner.pso.ftol;
  for (const CostVariant& variant : kVariants) {
    for (const double variance : {1.0, 0.05}) {
      const Costs now = jointEffectCosts(spec, 1.4, variance, variant, 1);
      const Costs at_one = jointEffectCosts(spec, 1.0, variance, variant, 1);
      std::printf(
          "JE calibrated %s, P = %.2f I: t0 = 1.4 s stay %.4f, join at once %.4f; "
          "t0 = 1.0 s stay %.4f, join at once %.4f\n",
          describe(variant).c_str(), variance, now.alone, now.cooperative, at_one.alone,
          at_one.cooperative);
      EXPECT_LT(now.cooperative, now.alone - ftol * (1.0 + now.alone)) << describe(variant);
      EXPECT_GT(at_one.cooperative, at_one.alone) << describe(variant);
    }
  }
}

}  // namespace
}  // namespace canopy::agents::planning
