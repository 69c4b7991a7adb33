#include "analysis/behaviours.h"

#include <gtest/gtest.h>

namespace canopy::analysis {
namespace {

constexpr TargetSet kNone = 0;
constexpr TargetSet I = 1, II = 2, III = 4, IV = 8;  // targets 0..3 as bits

// One UAV's per-step sets as a SetHistory with a single column.
SetHistory column(const std::vector<TargetSet>& sets) {
  SetHistory h;
  for (const TargetSet s : sets) h.push_back({s});
  return h;
}

TEST(MOwnership, RequiresMConsecutiveVisibleSteps) {
  const SetHistory V = column({I, I, I, kNone, I, I, I});
  const SetHistory M = mOwnership(V, 3);
  // k = 0: steps 0..2 all see I; k = 1..3: each window holds step 3; k = 4: 4..6.
  const std::vector<TargetSet> expected{I, kNone, kNone, kNone, I, I, I};
  for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_EQ(M[k][0], expected[k]) << "k=" << k;
}

TEST(MOwnership, LastStepsUseTheLastFullWindow) {
  // K = 5; m = 3: k = 3, 4, 5 all use [3, 5], where II is seen throughout but I is not.
  const SetHistory V = column({I, I, I, I | II, II, I | II});
  const SetHistory M = mOwnership(V, 3);
  EXPECT_EQ(M[3][0], II);
  EXPECT_EQ(M[4][0], II);
  EXPECT_EQ(M[5][0], II);
  EXPECT_EQ(M[1][0], I);  // [1, 3]
}

TEST(MOwnership, MOfOneIsVisibility) {
  const SetHistory V = {{I | III, II}, {kNone, II | IV}};
  EXPECT_EQ(mOwnership(V, 1), V);
}

TEST(OwnershipChange, TrajectoryHandoverZoneDefence) {
  // The paper's example: M_0 = ({I, III}, {II, IV}) → M_L = ({I, II}, {III, IV}) is reached by
  // UAV1 →(III) UAV2 and UAV2 →(II) UAV1.
  const SetHistory M = {{I | III, II | IV}, {I, IV}, {I | II, III | IV}};
  const std::vector<OwnershipChange> changes = ownershipChanges(M, 0, 2, 4);
  const std::vector<OwnershipChange> expected{{0, 1, 2}, {1, 0, 1}};
  EXPECT_EQ(changes, expected);
  EXPECT_TRUE(ownershipChange(M, 0, 2, 0, 1, 2));
  EXPECT_FALSE(ownershipChange(M, 0, 2, 0, 1, 0));  // I stays with UAV1
  EXPECT_FALSE(ownershipChange(M, 0, 1, 0, 1, 2));  // at k + 1 nobody owns III yet
  EXPECT_FALSE(ownershipChange(M, 1, 2, 0, 1, 0));  // k + L beyond the history
}

TEST(OwnershipChange, SharedOwnershipIsNotAChange) {
  const SetHistory M = {{I, kNone}, {I, I}};
  EXPECT_FALSE(ownershipChange(M, 0, 1, 0, 1, 0));  // t ∈ M_{i,k+L} still
  const SetHistory N = {{I, I}, {kNone, I}};
  EXPECT_FALSE(ownershipChange(N, 0, 1, 0, 1, 0));  // t ∈ M_{j,k} already
}

TEST(OwnershipState, NamedStatesThenMissesThenOther) {
  const std::vector<spec::NamedOwnership> named{
      {"M0", {{0, 2}, {1, 3}}, false},
      {"M*", {{0, 1}, {2, 3}}, true},
  };
  EXPECT_EQ(ownershipState({I | III, II | IV}, named, 4), "M0");
  EXPECT_EQ(ownershipState({II | IV, I | III}, named, 4), "Other");  // M0 is not permutable
  EXPECT_EQ(ownershipState({I | II, III | IV}, named, 4), "M*");
  EXPECT_EQ(ownershipState({III | IV, I | II}, named, 4), "M*");  // either robot order
  EXPECT_EQ(ownershipState({I | II, III}, named, 4), "Miss 1");   // IV owned by nobody
  EXPECT_EQ(ownershipState({I, kNone}, named, 4), "Miss >1");
  EXPECT_EQ(ownershipState({I | II | III, II | IV}, named, 4), "Other");
  EXPECT_EQ(ownershipState({I | II | III | IV, kNone}, {}, 4), "Other");
}

// Joint Effect in miniature: target I (0) is occluded at steps 5..10; k0 = 3, h = 2, L = 9, so
// the occluded window [k0 + h, k0 + L − h] = [5, 10] and the end k0 + L = 12.
struct JointEffect {
  SetHistory M = SetHistory(13, {kNone, kNone});
  SetHistory in_footprint = SetHistory(13, {kNone, kNone});
  std::vector<TargetSet> occluded = std::vector<TargetSet>(13, kNone);
  JointEffect() {
    for (int k = 5; k <= 10; ++k) occluded[k] = I;
    for (int k = 0; k < 13; ++k) {
      M[k] = {k < 5 || k > 10 ? I : II, II};  // UAV1 leaves I for II while I is hidden
      in_footprint[k] = {k < 5 || k > 10 ? I : II, II};
    }
  }
  bool aware() const { return occlusionAware(M, in_footprint, occluded, 0, 3, 9, 2); }
};

TEST(OcclusionAware, LeavingTheHiddenTargetAndReturningIsAware) {
  EXPECT_TRUE(JointEffect().aware());
}

TEST(OcclusionAware, WaitingIdleOverTheHiddenTargetIsNotAware) {
  JointEffect je;
  for (int k = 5; k <= 10; ++k) {
    je.M[k][0] = kNone;         // owns nothing ...
    je.in_footprint[k][0] = I;  // ... and keeps the occluded target in view
  }
  EXPECT_FALSE(je.aware());
}

TEST(OcclusionAware, WaitingForAllButOneStepDoesNotCountAsWaiting) {
  JointEffect je;
  for (int k = 5; k <= 10; ++k) {
    je.M[k][0] = kNone;
    je.in_footprint[k][0] = k == 10 ? kNone : I;  // drifts off at the interval's last step
  }
  EXPECT_TRUE(je.aware());
}

TEST(OcclusionAware, NeedsOwnershipBeforeAndAfter) {
  JointEffect before;
  before.M[3] = {kNone, II};  // condition 1 fails at k0
  EXPECT_FALSE(before.aware());
  JointEffect after;
  after.M[12] = {II, II};  // condition 3 fails at k0 + L
  EXPECT_FALSE(after.aware());
}

TEST(OcclusionAware, PresumesOcclusionOverTheWholeWindowIncludingItsBorders) {
  JointEffect late_start;
  late_start.occluded[5] = kNone;  // hidden only from step 6
  EXPECT_FALSE(late_start.aware());
  JointEffect early_end;
  early_end.occluded[10] = kNone;
  EXPECT_FALSE(early_end.aware());
  JointEffect out_of_range;
  EXPECT_FALSE(occlusionAware(out_of_range.M, out_of_range.in_footprint, out_of_range.occluded, 0,
                              3, 10, 2));
}

TEST(RunsOf, FindsMaximalInclusiveIntervals) {
  const std::vector<TargetSet> steps{kNone, I, I | II, II, kNone, I, I};
  EXPECT_EQ(runsOf(steps, 0), (std::vector<Interval>{{1, 2}, {5, 6}}));
  EXPECT_EQ(runsOf(steps, 1), (std::vector<Interval>{{2, 3}}));
  EXPECT_TRUE(runsOf(steps, 3).empty());
}

}  // namespace
}  // namespace canopy::analysis
