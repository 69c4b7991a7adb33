#include "metrics/ospa.h"

#include <gtest/gtest.h>

#include <cmath>

namespace canopy::metrics {
namespace {

TEST(Ospa, EmptySetsAndCardinalityPenalty) {
  Ospa ospa(50.0, 2.0);
  const std::vector<Vec2> none, one{Vec2(0, 0)};
  EXPECT_EQ(ospa(none, none), 0.0);
  EXPECT_EQ(ospa(one, none), 50.0);
  EXPECT_EQ(ospa(none, one), 50.0);
}

TEST(Ospa, MatchesHandComputedValues) {
  Ospa ospa(50.0, 2.0);
  // Two truths, two estimates 3 m and 4 m off after the best pairing (the crossed pairing costs
  // more): d = sqrt((9 + 16) / 2).
  const std::vector<Vec2> truth{Vec2(0, 0), Vec2(100, 0)};
  const std::vector<Vec2> est{Vec2(100, 4), Vec2(3, 0)};
  EXPECT_NEAR(ospa(truth, est), std::sqrt(12.5), 1e-12);
  // One truth, two estimates (1 m off and a false one): d = sqrt((1 + 2500) / 2).
  const std::vector<Vec2> lone{Vec2(0, 0)};
  const std::vector<Vec2> two{Vec2(1, 0), Vec2(0, 70)};
  EXPECT_NEAR(ospa(lone, two), std::sqrt(2501.0 / 2.0), 1e-12);
  // A miss farther than the cut-off counts as c: d = sqrt((2500 + 0) / 2) with c = 50.
  const std::vector<Vec2> far{Vec2(0, 80), Vec2(100, 0)};
  EXPECT_NEAR(ospa(truth, far), std::sqrt(2500.0 / 2.0), 1e-12);
}

TEST(Ospa, OrderOneIsTheMeanCutDistance) {
  Ospa ospa(10.0, 1.0);
  const std::vector<Vec2> truth{Vec2(0, 0), Vec2(5, 5)};
  const std::vector<Vec2> est{Vec2(0, 2), Vec2(5, 5), Vec2(40, 40)};
  EXPECT_NEAR(ospa(truth, est), (2.0 + 0.0 + 10.0) / 3.0, 1e-12);
}

}  // namespace
}  // namespace canopy::metrics
