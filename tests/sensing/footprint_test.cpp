#include "sensing/footprint.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace canopy::sensing {
namespace {

FootprintDef rectangle(double w, double h) {
  return {FootprintShape::rectangle, Vec2(w, h), 0.0};
}

TEST(Footprint, AxisAlignedRectangleIsClosed) {
  const Footprint f = Footprint::place(rectangle(20, 10), Vec2(5, 5), 0.0);
  EXPECT_TRUE(f.contains(Vec2(15, 10)));  // corner
  EXPECT_TRUE(f.contains(Vec2(-5, 0)));   // opposite corner
  EXPECT_TRUE(f.contains(Vec2(15, 5)));   // edge midpoint
  EXPECT_FALSE(f.contains(Vec2(15.001, 10)));
  EXPECT_FALSE(f.contains(Vec2(5, 10.001)));
  EXPECT_DOUBLE_EQ(f.area(), 200.0);
}

TEST(Footprint, RectangleWidthLiesAlongTheHeading) {
  // Heading north (ψ = π/2): 20 m along y, 10 m along x.
  const Footprint f = Footprint::place(rectangle(20, 10), Vec2(5, 5), std::numbers::pi / 2);
  EXPECT_TRUE(f.contains(Vec2(10, 15)));  // corner (5 + 5, 5 + 10)
  EXPECT_TRUE(f.contains(Vec2(0, -5)));   // corner (5 − 5, 5 − 10)
  EXPECT_FALSE(f.contains(Vec2(11, 5)));  // 6 m across the heading
  EXPECT_TRUE(f.contains(Vec2(5, 14.9)));
}

TEST(Footprint, RotatedCornerIsInsideAndJustBeyondIsNot) {
  const double psi = std::numbers::pi / 6;  // 30°
  const Footprint f = Footprint::place(rectangle(20, 10), Vec2(5, 5), psi);
  // Corner c + G(30°)(10, 5) = (5 + 10 cos30 − 5 sin30, 5 + 10 sin30 + 5 cos30), by hand.
  const Vec2 corner(5 + 10 * std::sqrt(3.0) / 2 - 2.5, 5 + 5 + 5 * std::sqrt(3.0) / 2);
  EXPECT_TRUE(f.contains(corner));
  const Vec2 outward = Vec2(std::cos(psi), std::sin(psi)) * 1e-6;  // along the heading
  EXPECT_FALSE(f.contains(corner + outward));
  EXPECT_TRUE(f.contains(corner - outward));
}

TEST(Footprint, BoundsOfARotatedRectangle) {
  // A 45° square of side 10: half-diagonal 5√2 in every axis direction.
  const Footprint f = Footprint::place(rectangle(10, 10), Vec2(0, 0), std::numbers::pi / 4);
  const Aabb box = f.bounds();
  EXPECT_NEAR(box.hi.x(), 5 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(box.lo.y(), -5 * std::sqrt(2.0), 1e-12);
}

TEST(Footprint, DiscIsClosed) {
  const Footprint f = Footprint::place({FootprintShape::disc, Vec2::Zero(), 12.0}, Vec2(1, 1), 0.7);
  EXPECT_TRUE(f.contains(Vec2(13, 1)));
  EXPECT_FALSE(f.contains(Vec2(13.0001, 1)));
  EXPECT_FALSE(f.contains(Vec2(10, 10)));  // distance 12.73
  EXPECT_NEAR(f.area(), std::numbers::pi * 144, 1e-9);
  EXPECT_EQ(f.bounds().lo, Vec2(-11, -11));
}

TEST(Footprint, PointsFromTheUnitSquareFallInside) {
  const Footprint rect = Footprint::place(rectangle(8, 4), Vec2(3, -2), 1.1);
  const Footprint disc =
      Footprint::place({FootprintShape::disc, Vec2::Zero(), 5.0}, Vec2(3, -2), 0.0);
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 20; ++j) {
      EXPECT_TRUE(rect.contains(rect.pointFromUnitSquare(i / 20.0, j / 20.0)));
      EXPECT_TRUE(disc.contains(disc.pointFromUnitSquare(i / 20.0, j / 20.0)));
    }
  }
}

}  // namespace
}  // namespace canopy::sensing
