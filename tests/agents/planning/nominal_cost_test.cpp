#include "agents/planning/nominal_cost.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "core/random.h"
#include "tests/agents/planning/cost_test_support.h"
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

using cost_test::hoveringUav;
using cost_test::settings;
using cost_test::target;

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
        const double stage =
            s.custody_radius > 0.0
                ? std::exp(-s.custody_radius * s.custody_radius / (P(0, 0) + P(1, 1)))
                : (s.full_trace ? P.trace() : P(0, 0) + P(1, 1));
        J += std::pow(s.discount, k / S) * stage;
      }
    }
  }
  return J;
}

// cost_trace "custody": each stage term is exp(−r²/tr(P_pos)) of the literal recursion's P, and
// the terminal penalty weighs an unseen track by that probability at m = H: w·d·exp(−r²/tr_H).
TEST(NominalCost, CustodyIsTheRayleighTailOfTheLiteralRecursion) {
  std::vector<UavState> uavs(1);
  uavs[0].position = Vec2(-3, 1);
  uavs[0].footprint.size = Vec2(12, 8);
  std::vector<Plan> plans(1);
  plans[0].velocities = {Vec2(3, 0), Vec2(2, 1), Vec2(0, 0)};
  // One walker the footprint passes over, one it never holds (30 m off, variance 4 m²).
  const std::vector<TargetGaussian> targets{target({-2, 0}, {2.5, 0}),
                                            target({30, 0}, {0, 0}, 4.0)};
  const OcclusionMap map;
  CostSettings s = settings(3, false);
  s.custody_radius = 5.0;
  const double expected = literalCost(targets, uavs, plans, s, map);
  EXPECT_NEAR(nominalCost({targets, uavs, &map, s}, plans), expected, 1e-12 + 1e-9 * expected);
  // The unseen track's P_pos at m = H = 3 by hand, per axis: 4 + 3²·4 from P₀ (no cross term),
  // and the noise of each step i = 1, 2, 3 carried n = 3 − i steps on, σ_a² (Δ⁴/4 + n Δ³ + n² Δ²)
  // with σ_a = Δ = 1: 6.25 + 2.25 + 0.25.
  const double per_axis = 4.0 + 9.0 * 4.0 + (6.25 + 2.25 + 0.25);
  const double loss = std::exp(-25.0 / (2.0 * per_axis));
  // The UAV ends at (−3, 1) + (3, 0) + (2, 1) + (0, 0) = (2, 2); the walker at 30 m stays put.
  const double distance = (Vec2(30, 0) - Vec2(2, 2)).norm();
  CostSettings with_penalty = s;
  with_penalty.terminal_penalty = true;
  const double J_penalty = nominalCost({targets, uavs, &map, with_penalty}, plans);
  EXPECT_NEAR(J_penalty - expected, with_penalty.terminal_penalty_weight * distance * loss, 1e-9);
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
