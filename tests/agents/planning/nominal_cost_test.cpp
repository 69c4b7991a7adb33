#include "agents/planning/nominal_cost.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "core/random.h"
#include "sensing/footprint.h"
#include "sensing/noise.h"

namespace canopy::agents::planning {
namespace {

constexpr double kPi = std::numbers::pi;

// Hand-computed cases: one target with P₀ = I₄, σ_a = 1, Δ = 1, α = 0.3, r0 = 2 m, a 20 × 20 m
// footprint. Per axis, P₀ = [[1, 0], [0, 1]] and
//   P⁻ = F P₀ Fᵀ + Q = [[1 + 1 + 1/4, 1 + 1/2], [1 + 1/2, 1 + 1]] = [[2.25, 1.5], [1.5, 2]].
// With the bearing along an axis R is diagonal, so each axis is a scalar Kalman update:
//   p⁺ = p − p²/(p + r),  c⁺ = c − p c/(p + r),  v⁺ = v − c²/(p + r).
struct Axis {
  double p, c, v;  // position variance, position-velocity covariance, velocity variance
};
Axis predictAxis(Axis a) {  // F a Fᵀ + Q, Δ = 1, σ_a = 1
  return {a.p + 2 * a.c + a.v + 0.25, a.c + a.v + 0.5, a.v + 1.0};
}
Axis updateAxis(Axis a, double r) {
  const double s = a.p + r;
  return {a.p - a.p * a.p / s, a.c - a.p * a.c / s, a.v - a.c * a.c / s};
}

UavState hoveringUav(Vec2 position) {
  UavState u;
  u.position = position;
  return u;
}

TargetGaussian target(Vec2 position, Vec2 velocity, double variance = 1.0) {
  TargetGaussian t;
  t.x << position, velocity;
  t.P = variance * Mat4::Identity();
  return t;
}

CostSettings settings(int horizon, bool terminal) {
  CostSettings s;
  s.horizon = horizon;
  s.terminal_penalty = terminal;
  return s;
}

double cost(const std::vector<TargetGaussian>& targets, const std::vector<UavState>& uavs,
            const std::vector<Plan>& plans, const CostSettings& s,
            const OcclusionMap* map = nullptr) {
  return nominalCost(PlanningProblem{targets, uavs, map, s}, plans);
}

TEST(NominalCost, TargetInFootprintOneStep) {
  // z₁ = (1, 0): d = max(2, 1) = 2, ρ = 0, R = diag(0.3·0.1·2, 0.3·0.1·π·2).
  const double rx = 0.06, ry = 0.06 * kPi;
  const double expected = 2.25 * rx / (2.25 + rx) + 2.25 * ry / (2.25 + ry);
  const std::vector<TargetGaussian> targets{target({1, 0}, {0, 0})};
  const std::vector<UavState> uavs{hoveringUav({0, 0})};
  const std::vector<Plan> plans{hoverPlan(1)};
  EXPECT_NEAR(cost(targets, uavs, plans, settings(1, false)), expected, 1e-12);
  // Seen at m = H: the terminal penalty adds nothing.
  EXPECT_NEAR(cost(targets, uavs, plans, settings(1, true)), expected, 1e-12);
}

TEST(NominalCost, MovingTargetInFootprintTwoSteps) {
  // ξ = (0, 0, 3, 0): z₁ = (3, 0) with d = 3, z₂ = (6, 0) with d = 6; ρ = 0 both times.
  const double r1x = 0.3 * 0.1 * 3, r1y = r1x * kPi, r2x = 0.3 * 0.1 * 6, r2y = r2x * kPi;
  const Axis x1 = updateAxis(predictAxis({1, 0, 1}), r1x);
  const Axis y1 = updateAxis(predictAxis({1, 0, 1}), r1y);
  const Axis x2 = updateAxis(predictAxis(x1), r2x);
  const Axis y2 = updateAxis(predictAxis(y1), r2y);
  const double expected = (x1.p + y1.p) + (x2.p + y2.p);
  const std::vector<TargetGaussian> targets{target({0, 0}, {3, 0})};
  const std::vector<UavState> uavs{hoveringUav({0, 0})};
  EXPECT_NEAR(cost(targets, uavs, {hoverPlan(2)}, settings(2, true)), expected, 1e-12);
  // Discount γ = 0.5 weighs the second step by one half.
  CostSettings discounted = settings(2, true);
  discounted.discount = 0.5;
  EXPECT_NEAR(cost(targets, uavs, {hoverPlan(2)}, discounted), (x1.p + y1.p) + 0.5 * (x2.p + y2.p),
              1e-12);
}

TEST(NominalCost, TargetOutsideFootprintAndTerminalPenalty) {
  // Unobserved: tr(P⁻₁[pos]) = 2·2.25 = 4.5; P⁻₂ per axis: p = 2.25 + 2·1.5 + 2 + 0.25 = 7.5,
  // so tr = 15. The penalty: w·|p_{1,H} − z_H|·tr = 0.5·30·tr.
  const std::vector<TargetGaussian> targets{target({30, 0}, {0, 0})};
  const std::vector<UavState> uavs{hoveringUav({0, 0})};
  EXPECT_NEAR(cost(targets, uavs, {hoverPlan(1)}, settings(1, false)), 4.5, 1e-12);
  EXPECT_NEAR(cost(targets, uavs, {hoverPlan(1)}, settings(1, true)), 4.5 + 0.5 * 30 * 4.5, 1e-12);
  EXPECT_NEAR(cost(targets, uavs, {hoverPlan(2)}, settings(2, false)), 4.5 + 15.0, 1e-12);
  EXPECT_NEAR(cost(targets, uavs, {hoverPlan(2)}, settings(2, true)), 19.5 + 0.5 * 30 * 15.0,
              1e-12);
  // Full trace adds the velocity variances: per axis 2 at m = 1.
  CostSettings full = settings(1, false);
  full.full_trace = true;
  EXPECT_NEAR(cost(targets, uavs, {hoverPlan(1)}, full), 4.5 + 4.0, 1e-12);
}

TEST(NominalCost, OccludedTargetIsNeitherObservedNorPenalised) {
  const OcclusionMap map({world::TreeDef::disc({1, 0}, 2.0)});
  const std::vector<TargetGaussian> targets{target({1, 0}, {0, 0})};
  const std::vector<UavState> uavs{hoveringUav({0, 0})};
  EXPECT_NEAR(cost(targets, uavs, {hoverPlan(1)}, settings(1, false), &map), 4.5, 1e-12);
  EXPECT_NEAR(cost(targets, uavs, {hoverPlan(1)}, settings(1, true), &map), 4.5, 1e-12);
  EXPECT_NEAR(cost(targets, uavs, {hoverPlan(2)}, settings(2, true), &map), 19.5, 1e-12);
  // A tree elsewhere changes nothing.
  const OcclusionMap elsewhere({world::TreeDef::disc({-5, -5}, 2.0)});
  const double rx = 0.06, ry = 0.06 * kPi;
  EXPECT_NEAR(cost(targets, uavs, {hoverPlan(1)}, settings(1, false), &elsewhere),
              2.25 * rx / (2.25 + rx) + 2.25 * ry / (2.25 + ry), 1e-12);
}

TEST(NominalCost, UavFlyingTowardsTargetSeesItAtTheSecondStep) {
  // a = (5, 0): p₁ = (5, 0) is 13 m from z = (18, 0) (outside the 10 m half-width), p₂ = (10, 0)
  // is 8 m away: d = 8, R = diag(0.3·0.8, 0.3·0.8·π). Per axis p⁻₂ = 7.5 (as above).
  const double rx = 0.24, ry = 0.24 * kPi;
  const double expected = 4.5 + 7.5 * rx / (7.5 + rx) + 7.5 * ry / (7.5 + ry);
  Plan east;
  east.velocities = {Vec2(5, 0), Vec2(5, 0)};
  const std::vector<TargetGaussian> targets{target({18, 0}, {0, 0})};
  const std::vector<UavState> uavs{hoveringUav({0, 0})};
  EXPECT_NEAR(cost(targets, uavs, {east}, settings(2, true)), expected, 1e-12);
  // 8 m/s is clamped to v_max = 5 m/s, as the world does: the same cost.
  Plan fast;
  fast.velocities = {Vec2(8, 0), Vec2(8, 0)};
  EXPECT_NEAR(cost(targets, uavs, {fast}, settings(2, true)), expected, 1e-12);
}

TEST(NominalCost, FootprintTurnsWithThePlannedHeadingOnlyWhenYawFollowsVelocity) {
  // A 30 m (along ψ) × 4 m (across) footprint, a = (0, 5): p₁ = (0, 5), z = (0, 12), 7 m north.
  // Yaw following velocity: ψ = π/2, z lies along the heading, inside. d = 7, ρ = π/2, so
  // R = diag(bearing, range) = diag(0.3·0.1·π·7, 0.3·0.1·7). Fixed yaw ψ = 0: 7 m across, outside.
  UavState uav = hoveringUav({0, 0});
  uav.footprint.size = Vec2(30, 4);
  Plan north;
  north.velocities = {Vec2(0, 5)};
  const std::vector<TargetGaussian> targets{target({0, 12}, {0, 0})};
  const double rx = 0.21 * kPi, ry = 0.21;
  uav.yaw_mode = world::YawMode::velocity;
  EXPECT_NEAR(cost(targets, {uav}, {north}, settings(1, false)),
              2.25 * rx / (2.25 + rx) + 2.25 * ry / (2.25 + ry), 1e-12);
  uav.yaw_mode = world::YawMode::fixed;
  EXPECT_NEAR(cost(targets, {uav}, {north}, settings(1, false)), 4.5, 1e-12);
}

TEST(NominalCost, TerminalPenaltyChargesDistancesGreedily) {
  // H = 1, both targets unseen. T1 (30, 0) with P₀ = 2 I: per axis p⁻ = 2 + 2 + 0.25, tr = 8.5.
  // T2 (0, 40) with P₀ = I: tr = 4.5. Stage cost 13. T1 goes first (larger trace) to A at (0, 0)
  // (30 m against B's ≥ 100 m): 0.5·30·8.5, D_A = 30. T2: A costs 30 + 40 = 70.
  const std::vector<TargetGaussian> targets{target({30, 0}, {0, 0}, 2.0),
                                            target({0, 40}, {0, 0}, 1.0)};
  const std::vector<Plan> plans{hoverPlan(1), hoverPlan(1)};
  // B at (0, 100): 60 < 70, T2 goes to B.
  EXPECT_NEAR(cost(targets, {hoveringUav({0, 0}), hoveringUav({0, 100})}, plans, settings(1, true)),
              13.0 + 0.5 * 30 * 8.5 + 0.5 * 60 * 4.5, 1e-9);
  // B at (0, 120): 80 > 70, T2 goes to A as well, charged its distance to T1 first.
  EXPECT_NEAR(cost(targets, {hoveringUav({0, 0}), hoveringUav({0, 120})}, plans, settings(1, true)),
              13.0 + 0.5 * 30 * 8.5 + 0.5 * 70 * 4.5, 1e-9);
}

// A second, literal implementation: information form with explicit inverses, the sensing
// library's R and Footprint::place with ψ = atan2 of the velocity. With S = s.substeps samples per
// action (τ = Δ/S) every sample predicts with F(τ), Q(τ) and adds Hᵀ (S·R)⁻¹ H per UAV in view.
double literalCost(const std::vector<TargetGaussian>& targets, const std::vector<UavState>& uavs,
                   const std::vector<Plan>& plans, const CostSettings& s, const OcclusionMap& map) {
  const int H = s.horizon, S = s.substeps;
  const double dt = s.period / S, q = s.sigma_a * s.sigma_a;
  Mat4 F = Mat4::Identity();
  F(0, 2) = F(1, 3) = dt;
  Mat4 Q = Mat4::Zero();
  for (int k = 0; k < 2; ++k) {
    Q(k, k) = q * std::pow(dt, 4) / 4;
    Q(k, k + 2) = Q(k + 2, k) = q * std::pow(dt, 3) / 2;
    Q(k + 2, k + 2) = q * dt * dt;
  }
  Mat24 Hobs = Mat24::Zero();
  Hobs(0, 0) = Hobs(1, 1) = 1;
  std::vector<std::vector<Vec2>> pos(uavs.size());
  std::vector<std::vector<sensing::Footprint>> fp(uavs.size());
  for (std::size_t i = 0; i < uavs.size(); ++i) {
    Vec2 p = uavs[i].position;
    double yaw = uavs[i].yaw;
    for (int m = 0; m < H; ++m) {
      Vec2 a = plans[i].velocities[m];
      if (a.norm() > uavs[i].v_max) a *= uavs[i].v_max / a.norm();
      if (uavs[i].yaw_mode == world::YawMode::velocity && a.norm() > 1e-6) {
        yaw = std::atan2(a.y(), a.x());
      }
      for (int sample = 0; sample < S; ++sample) {
        p += a * dt;
        pos[i].push_back(p);
        fp[i].push_back(sensing::Footprint::place(uavs[i].footprint, p, yaw));
      }
    }
  }
  double J = 0;
  for (const TargetGaussian& t : targets) {
    Vec4 x = t.x;
    Mat4 P = t.P;
    for (int k = 0; k < H * S; ++k) {
      x = F * x;
      P = F * P * F.transpose() + Q;
      Mat4 information = P.inverse();
      const Vec2 z = x.head<2>();
      for (std::size_t i = 0; i < uavs.size(); ++i) {
        if (map.occludes(z) || !fp[i][k].contains(z)) continue;
        const Mat2 R = S * sensing::rangeBearingCovariance(z, pos[i][k], uavs[i].quality);
        information += Hobs.transpose() * R.inverse() * Hobs;
      }
      P = information.inverse();
      if ((k + 1) % S == 0) {
        J += std::pow(s.discount, k / S) * (s.full_trace ? P.trace() : P(0, 0) + P(1, 1));
      }
    }
  }
  return J;
}

TEST(NominalCost, SubstepsMatchTheLiteralRecursionAndPartialPreparation) {
  // Two UAVs, one flying over a walker that passes under a small tree between plan instants.
  std::vector<UavState> uavs(2);
  uavs[0].position = Vec2(-3, 1);
  uavs[0].yaw_mode = world::YawMode::velocity;
  uavs[0].footprint.size = Vec2(12, 8);
  uavs[1].position = Vec2(6, -4);
  uavs[1].footprint.shape = sensing::FootprintShape::disc;
  uavs[1].footprint.radius = 7;
  std::vector<Plan> plans(2);
  plans[0].velocities = {Vec2(3, 0), Vec2(2, 1), Vec2(0, 0)};
  plans[1].velocities = {Vec2(-1, 2), Vec2(1, 0), Vec2(4, -4)};
  const std::vector<TargetGaussian> targets{target({-2, 0}, {2.5, 0}), target({5, -3}, {0, 1})};
  const OcclusionMap map({world::TreeDef::disc({1.2, 0}, 0.6)});  // hides the walker 0.24–0.72 s
  for (const int substeps : {1, 5}) {
    CostSettings s = settings(3, false);
    s.substeps = substeps;
    const PlanningProblem problem{targets, uavs, &map, s};
    const double expected = literalCost(targets, uavs, plans, s, map);
    EXPECT_NEAR(nominalCost(problem, plans), expected, 1e-9 * expected) << "S = " << substeps;
    NominalCost partial;
    const int free_agent[] = {0};
    partial.prepare(problem, free_agent, plans);
    EXPECT_NEAR(partial.evaluate(plans[0].velocities), expected, 1e-9 * expected);
  }
}

TEST(NominalCost, SubstepsKeepTheInformationOfATargetInViewAndSeeShortOcclusions) {
  // A target known to stand still under a hovering UAV, no process noise: S measurements of S·R
  // carry exactly the information of one measurement of R, so S changes nothing (hand-derived per
  // axis: p⁺ = 1 − 1/(1 + r) with r = α·0.1·r0 = 0.06 and 0.06·π).
  std::vector<TargetGaussian> still{target({1, 0}, {0, 0})};
  still[0].P.bottomRightCorner<2, 2>().setZero();  // known to stand still
  const std::vector<UavState> uav{hoveringUav({0, 0})};
  const double rx = 0.06, ry = 0.06 * kPi;
  for (const int substeps : {1, 5}) {
    CostSettings s = settings(1, false);
    s.sigma_a = 0.0;
    s.substeps = substeps;
    EXPECT_NEAR(cost(still, uav, {hoverPlan(1)}, s), rx / (1 + rx) + ry / (1 + ry), 1e-12);
  }
  // A walker hidden from 0.24 s to 0.72 s of the first action: invisible at the plan instants, so
  // with S = 1 the tree changes nothing; with S = 5 the samples at 0.4 s and 0.6 s are lost.
  const std::vector<TargetGaussian> walker{target({-2, 0}, {2.5, 0})};
  const OcclusionMap tree({world::TreeDef::disc({-0.8, 0}, 0.6)});
  for (const int substeps : {1, 5}) {
    CostSettings s = settings(2, false);
    s.substeps = substeps;
    const double open = cost(walker, uav, {hoverPlan(2)}, s);
    const double hidden = cost(walker, uav, {hoverPlan(2)}, s, &tree);
    if (substeps == 1) {
      EXPECT_EQ(open, hidden);
    } else {
      EXPECT_GT(hidden, open * 1.01);
    }
  }
}

TEST(NominalCost, MatchesLiteralInformationFormAndPartialPreparation) {
  // Three heterogeneous UAVs with overlapping footprints, off-axis bearings, a tree, H = 4.
  std::vector<UavState> uavs(3);
  uavs[0].position = Vec2(0, 0);
  uavs[0].yaw_mode = world::YawMode::velocity;
  uavs[0].footprint.size = Vec2(24, 12);
  uavs[1].position = Vec2(8, 5);
  uavs[1].yaw = 0.4;
  uavs[1].footprint.shape = sensing::FootprintShape::disc;
  uavs[1].footprint.radius = 9;
  uavs[1].quality = {0.5, 1.5};
  uavs[1].v_max = 3;
  uavs[2].position = Vec2(-6, 9);
  uavs[2].yaw = -0.7;
  std::vector<Plan> plans(3);
  plans[0].velocities = {Vec2(2, 1), Vec2(3, -1), Vec2(0, 0), Vec2(-1, 2)};
  plans[1].velocities = {Vec2(-1, 2), Vec2(4, 4), Vec2(1, 0), Vec2(0, -2)};
  plans[2].velocities = {Vec2(1, -1), Vec2(2, 0.5), Vec2(1, 1), Vec2(-3, 0)};
  std::vector<TargetGaussian> targets{target({3, 2}, {1, 0.5}), target({-4, 6}, {0.5, -1}, 2.0),
                                      target({10, -3}, {-1, 1}), target({60, 60}, {0, 0})};
  targets[1].P(0, 1) = targets[1].P(1, 0) = 0.3;
  targets[2].P(0, 2) = targets[2].P(2, 0) = 0.4;
  const OcclusionMap map({world::TreeDef::disc({12, -1}, 2.5)});
  CostSettings s = settings(4, false);
  s.discount = 0.9;
  const PlanningProblem problem{targets, uavs, &map, s};
  const double expected = literalCost(targets, uavs, plans, s, map);
  EXPECT_NEAR(nominalCost(problem, plans), expected, 1e-9 * expected);

  // Holding UAVs 0 and 2 fixed (their measurements fused beforehand) gives the same cost.
  NominalCost partial;
  const int free_agent[] = {1};
  partial.prepare(problem, free_agent, plans);
  EXPECT_NEAR(partial.evaluate(plans[1].velocities), expected, 1e-9 * expected);
  // With the terminal penalty too (the target at (60, 60) is unseen and charged).
  CostSettings with_penalty = s;
  with_penalty.terminal_penalty = true;
  const PlanningProblem penalised{targets, uavs, &map, with_penalty};
  const double full_joint = nominalCost(penalised, plans);
  EXPECT_GT(full_joint, expected + 100.0);
  partial.prepare(penalised, free_agent, plans);
  EXPECT_NEAR(partial.evaluate(plans[1].velocities), full_joint, 1e-9 * full_joint);
  s.full_trace = true;
  EXPECT_NEAR(nominalCost(PlanningProblem{targets, uavs, &map, s}, plans),
              literalCost(targets, uavs, plans, s, map), 1e-9 * expected);
}

// A batch of candidates gives each the bits it gets alone (the four lanes never mix), and the
// AVX2 copy gives the baseline's bits (the same operations, only encoded differently), over random
// scenes: UAVs and a ground robot, both occlusion models, an odd number of tracks, one and several
// free agents, S = 1 and 3, batches of 7 (one lane of the second group repeats the last).
TEST(NominalCost, BatchesAndInstructionSetsGiveEachCandidateItsBits) {
  std::vector<InstructionSet> sets = {InstructionSet::baseline};
  if (instructionSet() == InstructionSet::avx2) sets.push_back(InstructionSet::avx2);
  RandomStream rng(21, "instruction-set-test");
  std::vector<world::TreeDef> trees;
  for (int k = 0; k < 30; ++k) {
    trees.push_back(world::TreeDef::disc(Vec2(rng.uniform(-40, 40), rng.uniform(-40, 40)),
                                         rng.uniform(0.5, 3.0)));
  }
  const OcclusionMap map(std::move(trees));
  int compared = 0;
  for (int scene = 0; scene < 24; ++scene) {
    std::vector<UavState> uavs(4);
    for (int i = 0; i < 4; ++i) {
      uavs[i].position = Vec2(rng.uniform(-30, 30), rng.uniform(-30, 30));
      uavs[i].yaw = rng.uniform(-kPi, kPi);
      uavs[i].yaw_mode = i % 2 == 0 ? world::YawMode::velocity : world::YawMode::fixed;
      uavs[i].footprint.size = Vec2(rng.uniform(10, 30), rng.uniform(10, 30));
      if (scene % 2 == 1) uavs[i].occlusion = sensing::OcclusionModel::line_of_sight;
    }
    uavs[3].kind = world::AgentKind::ground;
    uavs[3].footprint.shape = sensing::FootprintShape::sector;
    uavs[3].footprint.radius = 25;
    uavs[3].occlusion = sensing::OcclusionModel::line_of_sight;
    std::vector<TargetGaussian> targets;
    for (int j = 0; j < 5; ++j) {
      targets.push_back(target(Vec2(rng.uniform(-30, 30), rng.uniform(-30, 30)),
                               Vec2(rng.uniform(-2, 2), rng.uniform(-2, 2)),
                               rng.uniform(0.2, 5.0)));
    }
    CostSettings s = settings(4, true);
    s.substeps = scene % 3 == 2 ? 3 : 1;
    const PlanningProblem problem{targets, uavs, &map, s};
    std::vector<Plan> plans(4);
    for (Plan& plan : plans) {
      for (int m = 0; m < s.horizon; ++m) {
        plan.velocities.push_back(Vec2(rng.uniform(-5, 5), rng.uniform(-5, 5)));
      }
    }
    const std::vector<int> free_agents =
        scene % 4 < 2 ? std::vector<int>{1} : std::vector<int>{0, 3, 2};
    NominalCost cost;
    cost.prepare(problem, free_agents, plans);
    for (int trial = 0; trial < 3; ++trial) {
      constexpr int kBatch = 7;
      std::vector<Vec2> actions;
      for (std::size_t k = 0; k < kBatch * free_agents.size() * s.horizon; ++k) {
        actions.push_back(Vec2(rng.uniform(-6, 6), rng.uniform(-6, 6)));
      }
      const std::size_t per_candidate = free_agents.size() * s.horizon;
      for (const InstructionSet set : sets) {
        std::vector<double> costs(kBatch);
        cost.evaluateWith(set, actions, costs);
        for (int c = 0; c < kBatch; ++c) {
          const double alone = cost.evaluate(
              std::span<const Vec2>(actions).subspan(c * per_candidate, per_candidate));
          ASSERT_EQ(std::bit_cast<std::uint64_t>(costs[c]), std::bit_cast<std::uint64_t>(alone))
              << "scene " << scene << ", trial " << trial << ", candidate " << c;
          ++compared;
        }
      }
    }
  }
  EXPECT_EQ(compared, 24 * 3 * 7 * static_cast<int>(sets.size()));
}

}  // namespace
}  // namespace canopy::agents::planning

namespace canopy::agents::planning {
namespace {

// Cost scope "reach" (docs/design-notes.md, issue 33) is the team cost of the problem reduced to
// the tracks a free UAV can reach and the teammates that can reach them: computed here by the
// team scope on that reduced problem, built by hand. Free UAV 0 at the origin (H = 3, v_max 5,
// 20 × 20 m footprint: reach 15 + 14.1 m); UAV 1 20 m east (a neighbour), UAV 2 1 km east.
TEST(NominalCost, ReachScopeIsTheTeamCostOfTheNeighbourhood) {
  const std::vector<UavState> uavs{hoveringUav({0, 0}), hoveringUav({20, 0}),
                                   hoveringUav({1000, 0})};
  const std::vector<TargetGaussian> all{
      target({5, 3}, {1, 0}),         // in reach
      target({200, 0}, {0, 1}, 4.0),  // beyond every reach: uncovered, charged in team scope
      target({25, -8}, {0, 0}, 2.0),  // in reach, and in UAV 1's footprint
      target({1000, 5}, {0, 0}),      // under UAV 2
  };
  const std::vector<TargetGaussian> near{all[0], all[2]};
  const std::vector<UavState> neighbours{uavs[0], uavs[1]};
  const std::vector<Plan> assumed{
      hoverPlan(3), Plan{std::vector<Vec2>{Vec2(1, 0), Vec2(1, 1), Vec2(0, 0)}}, hoverPlan(3)};
  const std::vector<Plan> assumed_near{assumed[0], assumed[1]};
  CostSettings reach = settings(3, true);
  reach.scope = CostScope::reach;
  const CostSettings team = settings(3, true);
  NominalCost scoped, reduced, whole;
  const int self[] = {0};
  scoped.prepare(PlanningProblem{all, uavs, nullptr, reach}, self, assumed);
  reduced.prepare(PlanningProblem{near, neighbours, nullptr, team}, self, assumed_near);
  whole.prepare(PlanningProblem{all, uavs, nullptr, team}, self, assumed);
  RandomStream rng(33, "reach-scope-test");
  int differs = 0;
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vec2> actions;
    for (int m = 0; m < 3; ++m) actions.emplace_back(rng.uniform(-5, 5), rng.uniform(-5, 5));
    const double j_reach = scoped.evaluate(actions);
    EXPECT_DOUBLE_EQ(j_reach, reduced.evaluate(actions)) << trial;
    // The track at (200, 0) is uncovered at m = H whatever UAV 0 does, so the team cost is
    // larger, by its stage costs and its share of the terminal penalty.
    EXPECT_GT(whole.evaluate(actions), j_reach) << trial;
    differs += whole.evaluate(actions) != j_reach;
  }
  EXPECT_EQ(differs, 50);
}

// Without the terminal penalty the scopes differ by a constant: the stage costs of the tracks
// out of reach do not depend on the free UAV's plan (the exact part of the argument).
TEST(NominalCost, ReachScopeWithoutPenaltyDiffersFromTeamByAConstant) {
  const std::vector<UavState> uavs{hoveringUav({0, 0}), hoveringUav({60, 0}),
                                   hoveringUav({-300, 40})};
  const std::vector<TargetGaussian> all{target({5, 3}, {1, 0}), target({65, 0}, {-1, 0}),
                                        target({-300, 45}, {0, 0}), target({10, -12}, {0, 1})};
  const std::vector<Plan> assumed{
      hoverPlan(3), Plan{std::vector<Vec2>{Vec2(-4, 0), Vec2(-4, 0), Vec2(-4, 0)}}, hoverPlan(3)};
  CostSettings reach = settings(3, false);
  reach.scope = CostScope::reach;
  NominalCost scoped, whole;
  const int self[] = {0};
  scoped.prepare(PlanningProblem{all, uavs, nullptr, reach}, self, assumed);
  whole.prepare(PlanningProblem{all, uavs, nullptr, settings(3, false)}, self, assumed);
  RandomStream rng(34, "reach-scope-constant");
  double offset = 0.0;
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vec2> actions;
    for (int m = 0; m < 3; ++m) actions.emplace_back(rng.uniform(-5, 5), rng.uniform(-5, 5));
    const double difference = whole.evaluate(actions) - scoped.evaluate(actions);
    if (trial == 0) offset = difference;
    EXPECT_NEAR(difference, offset, 1e-9 * (1.0 + offset)) << trial;
  }
  EXPECT_GT(offset, 1.0);  // the far track's stage costs (tr P grows from 2 m² over 3 steps)
}

}  // namespace
}  // namespace canopy::agents::planning

namespace canopy::agents::planning {
namespace {

// The clearance charge (docs/design-notes.md, "Plans that keep clear") of a UAV with a body:
// K₀ + K₁·(r_f + r_g + c − d) at each sample whose nominal position lies within r_f + r_g + c of
// a teammate's intended one, as for ground robots. Free UAV 0 hovers at the origin, UAV 1 hovers
// 1.5 m east (both r = 1 m, c = 0.2 m): each of the H = 3 samples is charged
// 10⁶ + 10⁶·(2.2 − 1.5) = 1.7·10⁶ m². UAVs without a body, or a UAV and a robot, are not.
TEST(NominalCost, AUavWithABodyIsChargedForComingWithinItsSeparationOfATeammate) {
  const std::vector<TargetGaussian> targets{target({3, 4}, {0, 0})};
  auto pair = [](double r0, double r1, world::AgentKind kind1) {
    std::vector<UavState> uavs{hoveringUav({0, 0}), hoveringUav({1.5, 0})};
    uavs[0].radius = r0;
    uavs[1].radius = r1;
    uavs[1].kind = kind1;
    return uavs;
  };
  const std::vector<Plan> plans{hoverPlan(3), hoverPlan(3)};
  const CostSettings s = settings(3, true);
  const int self[] = {0};
  auto costOf = [&](const std::vector<UavState>& uavs) {
    NominalCost cost;
    cost.prepare(PlanningProblem{targets, uavs, nullptr, s}, self, plans);
    return cost.evaluate(std::vector<Vec2>(3, Vec2::Zero()));
  };
  const double bare = costOf(pair(0.0, 0.0, world::AgentKind::uav));
  const double bodies = costOf(pair(1.0, 1.0, world::AgentKind::uav));
  EXPECT_NEAR(bodies - bare, 3 * 1.7e6, 1e-6 * 3 * 1.7e6);
  // One without a body: no separation to keep (the world does not hold them apart either).
  EXPECT_EQ(costOf(pair(1.0, 0.0, world::AgentKind::uav)), bare);
  EXPECT_EQ(costOf(pair(0.0, 1.0, world::AgentKind::uav)), bare);
  // A robot below a UAV: they never touch (different collision classes).
  const std::vector<UavState> robot_below = pair(1.0, 1.0, world::AgentKind::ground);
  std::vector<UavState> robot_bare = robot_below;
  robot_bare[0].radius = 0.0;
  EXPECT_EQ(costOf(robot_below), costOf(robot_bare));
  // Both free (a joint search): the pair is charged once per sample, as for two robots.
  const int both[] = {0, 1};
  auto jointCost = [&](const std::vector<UavState>& uavs) {
    NominalCost cost;
    cost.prepare(PlanningProblem{targets, uavs, nullptr, s}, both, plans);
    return cost.evaluate(std::vector<Vec2>(6, Vec2::Zero()));
  };
  EXPECT_NEAR(jointCost(pair(1.0, 1.0, world::AgentKind::uav)) -
                  jointCost(pair(0.0, 0.0, world::AgentKind::uav)),
              3 * 1.7e6, 1e-6 * 3 * 1.7e6);
}

// Two bodies that pass each other between two samples: the charge takes their closest approach
// on the interval, not only their distance at the samples (S = 1, Δ = 1 s, r = 1 m, c = 0.2 m).
// Free UAV 0 flies from (−2, 0) to (2, 0); UAV 1 hovers at (0, 1). At the one sample they are
// √5 ≈ 2.24 m apart (> 2.2 m), but at s = ½ only 1 m: 10⁶ + 10⁶·(2.2 − 1) = 2.2·10⁶ m².
// Both free, UAV 1 flying from (2, 1) to (−2, 1) the other way: the relative position runs from
// (−4, −1) to (4, −1), closest |(0, −1)| = 1 m at s = ½, the same charge once.
TEST(NominalCost, BodiesThatPassEachOtherBetweenSamplesAreChargedTheirClosestApproach) {
  const std::vector<TargetGaussian> targets{target({30, 40}, {0, 0})};
  CostSettings s = settings(1, false);
  s.substeps = 1;
  auto uav = [](Vec2 p, double radius) {
    UavState u = hoveringUav(p);
    u.radius = radius;
    return u;
  };
  const std::vector<Plan> plans{hoverPlan(1), hoverPlan(1)};
  const int self[] = {0};
  auto fixedCost = [&](double radius) {
    const std::vector<UavState> uavs{uav({-2, 0}, radius), uav({0, 1}, radius)};
    NominalCost cost;
    cost.prepare(PlanningProblem{targets, uavs, nullptr, s}, self, plans);
    return cost.evaluate(std::vector<Vec2>{Vec2(4, 0)});
  };
  EXPECT_NEAR(fixedCost(1.0) - fixedCost(0.0), 2.2e6, 1e-6);
  const int both[] = {0, 1};
  auto jointCost = [&](double radius) {
    const std::vector<UavState> uavs{uav({-2, 0}, radius), uav({2, 1}, radius)};
    NominalCost cost;
    cost.prepare(PlanningProblem{targets, uavs, nullptr, s}, both, plans);
    return cost.evaluate(std::vector<Vec2>{Vec2(4, 0), Vec2(-4, 0)});
  };
  EXPECT_NEAR(jointCost(1.0) - jointCost(0.0), 2.2e6, 1e-6);
}

// Cost scope "reach" leaves a teammate beyond the free agent's reach out of the information
// cost, but its body is still where its plan takes it: a robot 1 km away charges nothing to a
// free robot hovering 0.3 m from the origin (its path was once left at (0, 0) and charged
// 10⁶ + 10⁶·(0.5 + 0.5 + 0.2 − 0.3) at each of the 3 samples). The cost equals that of the
// problem without the far robot; a robot 0.5 m from the free one is charged as the rule says.
TEST(NominalCost, ReachScopeChargesATeammateOutOfReachWhereItIsNotAtTheOrigin) {
  const std::vector<TargetGaussian> targets{target({5, 3}, {1, 0})};
  auto robot = [](Vec2 p) {
    UavState u = hoveringUav(p);
    u.kind = world::AgentKind::ground;
    u.radius = 0.5;
    u.footprint.shape = sensing::FootprintShape::sector;
    u.footprint.radius = 10;
    return u;
  };
  CostSettings reach = settings(3, true);
  reach.scope = CostScope::reach;
  const int self[] = {0};
  auto costOf = [&](const std::vector<UavState>& uavs) {
    const std::vector<Plan> plans(uavs.size(), hoverPlan(3));
    NominalCost cost;
    cost.prepare(PlanningProblem{targets, uavs, nullptr, reach}, self, plans);
    return cost.evaluate(std::vector<Vec2>(3, Vec2::Zero()));
  };
  const double alone = costOf({robot({0.3, 0})});
  EXPECT_LT(alone, 1e6);  // no charge: nothing near
  EXPECT_EQ(costOf({robot({0.3, 0}), robot({1000, 0})}), alone);
  // The positive control: a teammate 0.5 m away, in reach, 0.7 m inside r_f + r_g + c = 1.2 m.
  const double near = costOf({robot({0.3, 0}), robot({0.3, 0.5})});
  // (Its camera changes the information part by far less than 10³ m²: tr P is a few m² here.)
  EXPECT_NEAR(near - alone, 3 * 1.7e6, 1e3);
}

}  // namespace
}  // namespace canopy::agents::planning
