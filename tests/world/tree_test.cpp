#include "world/tree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace canopy::world {
namespace {

TEST(Tree, DiscInteriorIsStrictRimIsNotInside) {
  const TreeDef tree = TreeDef::disc(Vec2(0, 0), 2.0);
  EXPECT_TRUE(strictlyInside(tree, Vec2(1.999, 0)));
  EXPECT_FALSE(strictlyInside(tree, Vec2(2.0, 0)));  // on the rim: visible
  EXPECT_FALSE(strictlyInside(tree, Vec2(0, -2.0)));
  EXPECT_FALSE(strictlyInside(tree, Vec2(1.5, 1.5)));  // |p| = 2.12
}

TEST(Tree, PolygonStoresCounterClockwiseCentroidAndEqualAreaRadius) {
  // A clockwise 4 x 2 rectangle: area 8, centroid (2, 1).
  const TreeDef tree = TreeDef::polygon({{0, 0}, {0, 2}, {4, 2}, {4, 0}});
  EXPECT_GT(signedArea(tree.vertices), 0.0);
  EXPECT_NEAR(tree.centre.x(), 2.0, 1e-12);
  EXPECT_NEAR(tree.centre.y(), 1.0, 1e-12);
  EXPECT_NEAR(tree.radius, std::sqrt(8.0 / std::numbers::pi), 1e-12);
  EXPECT_TRUE(strictlyInside(tree, Vec2(3.9, 1.9)));
  EXPECT_FALSE(strictlyInside(tree, Vec2(4.0, 1.0)));  // on an edge
  EXPECT_FALSE(strictlyInside(tree, Vec2(4.1, 1.0)));
}

TEST(Tree, ConvexityRejectsReflexCollinearAndSelfIntersectingPolygons) {
  EXPECT_TRUE(isStrictlyConvex({{0, 0}, {1, 0}, {0, 1}}));
  EXPECT_TRUE(isStrictlyConvex({{0, 0}, {0, 1}, {1, 0}}));                     // clockwise is fine
  EXPECT_FALSE(isStrictlyConvex({{0, 0}, {2, 0}, {1, 0.5}, {2, 2}, {0, 2}}));  // reflex vertex
  EXPECT_FALSE(isStrictlyConvex({{0, 0}, {1, 0}, {2, 0}, {1, 1}}));            // three in a line
  EXPECT_FALSE(isStrictlyConvex({{0, 0}, {2, 2}, {2, 0}, {0, 2}}));            // a bow tie
  EXPECT_FALSE(isStrictlyConvex({{0, 0}, {1, 0}}));
}

TEST(Tree, SegmentEntryIntoADiscMatchesTheQuadraticRoot) {
  const TreeDef tree = TreeDef::disc(Vec2(5, 0), 1.0);
  // From (0,0) to (10,0): enters at x = 4, fraction 0.4.
  EXPECT_NEAR(segmentEntry(tree, Vec2(0, 0), Vec2(10, 0)), 0.4, 1e-12);
  // Passing at distance exactly 1 touches the rim only: not a crossing.
  EXPECT_LT(segmentEntry(tree, Vec2(0, 1), Vec2(10, 1)), 0.0);
  // Passing at distance 0.6: enters at x = 5 − 0.8 = 4.2.
  EXPECT_NEAR(segmentEntry(tree, Vec2(0, 0.6), Vec2(10, 0.6)), 0.42, 1e-12);
  // Ending before the crown, or starting inside.
  EXPECT_LT(segmentEntry(tree, Vec2(0, 0), Vec2(3.9, 0)), 0.0);
  EXPECT_EQ(segmentEntry(tree, Vec2(5.5, 0), Vec2(10, 10)), 0.0);
  // Ending inside counts.
  EXPECT_NEAR(segmentEntry(tree, Vec2(0, 0), Vec2(5, 0)), 0.8, 1e-12);
}

TEST(Tree, SegmentEntryIntoAPolygonByClipping) {
  const TreeDef square = TreeDef::polygon({{2, -1}, {4, -1}, {4, 1}, {2, 1}});
  EXPECT_NEAR(segmentEntry(square, Vec2(0, 0), Vec2(10, 0)), 0.2, 1e-12);
  EXPECT_LT(segmentEntry(square, Vec2(0, 1), Vec2(10, 1)), 0.0);   // along an edge
  EXPECT_LT(segmentEntry(square, Vec2(2, 3), Vec2(6, -1)), 0.0);   // x + y = 5 touches (4, 1)
  EXPECT_EQ(segmentEntry(square, Vec2(3, 0), Vec2(3, 10)), 0.0);   // starts inside
  EXPECT_LT(segmentEntry(square, Vec2(0, 0), Vec2(1.5, 0)), 0.0);  // stops short
}

TEST(Tree, BoundsHoldTheCrown) {
  const Aabb disc = bounds(TreeDef::disc(Vec2(1, 2), 3));
  EXPECT_EQ(disc.lo, Vec2(-2, -1));
  EXPECT_EQ(disc.hi, Vec2(4, 5));
  const Aabb poly = bounds(TreeDef::polygon({{0, 0}, {3, 1}, {1, 4}}));
  EXPECT_EQ(poly.lo, Vec2(0, 0));
  EXPECT_EQ(poly.hi, Vec2(3, 4));
}

TEST(Tree, SolidPartsTrunksAndWalls) {
  // Default trunks: 0.1 r within [0.05, 0.5] m, never wider than the crown.
  EXPECT_DOUBLE_EQ(TreeDef::disc(Vec2(0, 0), 2.0).trunk_radius, 0.2);
  EXPECT_DOUBLE_EQ(TreeDef::disc(Vec2(0, 0), 9.0).trunk_radius, 0.5);
  EXPECT_DOUBLE_EQ(TreeDef::disc(Vec2(0, 0), 0.2).trunk_radius, 0.05);
  EXPECT_DOUBLE_EQ(TreeDef::disc(Vec2(0, 0), 0.03).trunk_radius, 0.03);
  TreeDef wall = TreeDef::polygon({{2, -1}, {4, -1}, {4, 1}, {2, 1}});
  EXPECT_TRUE(isWall(wall));
  EXPECT_FALSE(isWall(TreeDef::disc(Vec2(0, 0), 1.0)));
  // Points: to the nearest edge or corner, 0 inside.
  EXPECT_DOUBLE_EQ(solidDistance(wall, Vec2(0, 0)), 2.0);
  EXPECT_DOUBLE_EQ(solidDistance(wall, Vec2(7, 5)), 5.0);  // (4, 1) + (3, 4)
  EXPECT_DOUBLE_EQ(solidDistance(wall, Vec2(3, 0)), 0.0);
  // Segments: crossing it, passing 0.5 above, parallel to an edge, ending short.
  EXPECT_DOUBLE_EQ(solidDistance(wall, Vec2(0, 0), Vec2(10, 0)), 0.0);
  EXPECT_DOUBLE_EQ(solidDistance(wall, Vec2(0, 1.5), Vec2(10, 1.5)), 0.5);
  // Along x + y = 8: the corner (4, 1) is 3/√2 from it.
  EXPECT_NEAR(solidDistance(wall, Vec2(3, 5), Vec2(9, -1)), 3.0 / std::sqrt(2.0), 1e-12);
  EXPECT_DOUBLE_EQ(solidDistance(wall, Vec2(0, 0), Vec2(1.5, 0)), 0.5);
  // A trunk: the segment's distance to the centre less its radius.
  TreeDef tree = TreeDef::disc(Vec2(5, 0), 3.0);
  tree.trunk_radius = 0.3;
  EXPECT_NEAR(solidDistance(tree, Vec2(0, 1), Vec2(10, 1)), 0.7, 1e-12);
  // Nearest point of (0, 0) → (3, 4) to (5, 0): (1.8, 2.4), 4 m away.
  EXPECT_NEAR(solidDistance(tree, Vec2(0, 0), Vec2(3, 4)), 4.0 - 0.3, 1e-12);
  EXPECT_NEAR(solidDistance(tree, Vec2(5, 0)), -0.3, 1e-12);
  // A polygon with a trunk is a crown: only the trunk at its centroid is solid.
  wall.trunk_radius = 0.2;
  EXPECT_FALSE(isWall(wall));
  EXPECT_NEAR(solidDistance(wall, Vec2(0, 0), Vec2(10, 0)), -0.2, 1e-12);
}

}  // namespace
}  // namespace canopy::world
