#include "world/path.h"

#include <gtest/gtest.h>

namespace canopy::world {
namespace {

TEST(Path, WaypointsInterpolateLinearlyAndHoldAtTheEnds) {
  const Path path =
      Path::throughPoints({{2.0, Vec2(0, 0)}, {4.0, Vec2(10, 0)}, {8.0, Vec2(10, 20)}});
  EXPECT_EQ(path.positionAt(0.0), Vec2(0, 0));  // waits at the first point
  EXPECT_EQ(path.positionAt(3.0), Vec2(5, 0));  // halfway along 0→10 in 2 s
  EXPECT_EQ(path.positionAt(4.0), Vec2(10, 0));
  EXPECT_EQ(path.positionAt(6.0), Vec2(10, 10));
  EXPECT_EQ(path.positionAt(99.0), Vec2(10, 20));  // stays at the last point
  EXPECT_EQ(path.velocityAt(3.0), Vec2(5, 0));     // 10 m in 2 s
  EXPECT_EQ(path.velocityAt(5.0), Vec2(0, 5));     // 20 m in 4 s
  EXPECT_EQ(path.velocityAt(1.0), Vec2::Zero());
  EXPECT_EQ(path.velocityAt(8.0), Vec2::Zero());
}

TEST(Path, ConstantVelocityMovesFromItsStart) {
  const Path path = Path::constantVelocity(Vec2(1, 2), Vec2(0.5, -1));
  EXPECT_EQ(path.positionAt(0.0), Vec2(1, 2));
  EXPECT_EQ(path.positionAt(4.0), Vec2(3, -2));
  EXPECT_EQ(path.velocityAt(100.0), Vec2(0.5, -1));
}

TEST(Path, SinglePointIsStationary) {
  const Path path = Path::throughPoints({{0.0, Vec2(3, 4)}});
  EXPECT_EQ(path.positionAt(10.0), Vec2(3, 4));
  EXPECT_EQ(path.velocityAt(10.0), Vec2::Zero());
}

}  // namespace
}  // namespace canopy::world
