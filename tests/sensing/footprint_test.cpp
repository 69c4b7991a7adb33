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

FootprintDef sector(double range, double angle) {
  FootprintDef def;
  def.shape = FootprintShape::sector;
  def.radius = range;
  def.angle = angle;
  return def;
}

TEST(Footprint, SectorHoldsWhatLiesWithinRangeAndHalfTheAngleOfTheHeading) {
  constexpr double kPi = std::numbers::pi;
  // Apex (2, 1), heading north, 90° wide, 10 m: the quarter disc between the bearings 45° and
  // 135° from the x axis.
  const Footprint f = Footprint::place(sector(10, kPi / 2), Vec2(2, 1), kPi / 2);
  EXPECT_TRUE(f.contains(Vec2(2, 1)));   // the apex
  EXPECT_TRUE(f.contains(Vec2(2, 11)));  // straight ahead at the range
  EXPECT_FALSE(f.contains(Vec2(2, 11.001)));
  EXPECT_TRUE(f.contains(Vec2(5, 4)));       // on the 45° edge
  EXPECT_FALSE(f.contains(Vec2(5.01, 4)));   // just outside it
  EXPECT_TRUE(f.contains(Vec2(-1, 4)));      // on the 135° edge
  EXPECT_FALSE(f.contains(Vec2(2, 0.5)));    // behind
  EXPECT_TRUE(f.contains(Vec2(9, 8)));       // on the 45° edge, √98 = 9.90 m from the apex
  EXPECT_FALSE(f.contains(Vec2(9.1, 8.1)));  // the same bearing, 10.04 m
  EXPECT_NEAR(f.area(), 0.5 * (kPi / 2) * 100, 1e-12);  // ½ θ r²
  // Bounds: the apex, the arc's ends (2 ± 7.07, 8.07) and its top (2, 11).
  const Aabb box = f.bounds();
  EXPECT_NEAR(box.lo.x(), 2 - 10 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(box.hi.x(), 2 + 10 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(box.lo.y(), 1.0, 1e-12);
  EXPECT_NEAR(box.hi.y(), 11.0, 1e-12);
  // A 270° sector facing east spans ±135°: it reaches the axis extremes east, north and south;
  // westward only its arc's ends at ±135°, x = −4/√2.
  const Aabb wide = Footprint::place(sector(4, 1.5 * kPi), Vec2(0, 0), 0.0).bounds();
  EXPECT_NEAR(wide.lo.x(), -4.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(wide.lo.y(), -4.0, 1e-12);
  EXPECT_NEAR(wide.hi.y(), 4.0, 1e-12);
  EXPECT_NEAR(wide.hi.x(), 4.0, 1e-12);
}

TEST(Footprint, SectorPointsFromTheUnitSquareAreUniformOverItsArea) {
  // Area-uniform over a sector of range r: the distance from the apex has density 2ρ/r², so its
  // mean is 2r/3 and a fraction ¼ of the points lies within r/2.
  const Footprint f = Footprint::place(sector(9, 1.2), Vec2(-3, 2), 0.4);
  const int n = 200;
  double sum = 0.0;
  int near = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Vec2 p = f.pointFromUnitSquare((i + 0.5) / n, (j + 0.5) / n);
      ASSERT_TRUE(f.contains(p));
      const double rho = (p - f.centre).norm();
      sum += rho;
      near += rho <= 4.5;
    }
  }
  EXPECT_NEAR(sum / (n * n), 6.0, 1e-3);
  EXPECT_NEAR(static_cast<double>(near) / (n * n), 0.25, 1e-3);
}

}  // namespace
}  // namespace canopy::sensing
