// Crowns Box2D cannot build: every one is refused by box2dProblem (which the loader calls with
// the field) and by World's constructor with an exception, never by Box2D's assertion. The
// families are generated over scale, offset and rotation, not only the examples; the
// property test builds a World from every random polygon that is accepted (an assertion inside
// Box2D would abort this test).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "world/tree.h"
#include "world/world.h"

namespace canopy::world {
namespace {

std::vector<Vec2> placed(std::vector<Vec2> shape, double scale, double angle, const Vec2& offset) {
  const double c = std::cos(angle), s = std::sin(angle);
  for (Vec2& v : shape) v = offset + scale * Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
  return shape;
}

std::vector<Vec2> regular(int n, double radius) {
  std::vector<Vec2> v;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    v.emplace_back(radius * std::cos(a), radius * std::sin(a));
  }
  return v;
}

// Builds a world holding `tree`: true when it was built, false when the constructor refused it.
bool builds(const TreeDef& tree) {
  WorldDef def;
  def.aoi = {Vec2::Constant(-kMaxTreeCoordinate), Vec2::Constant(kMaxTreeCoordinate)};
  def.trees.push_back(tree);
  try {
    World world(def);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

void expectRefused(const std::vector<Vec2>& vertices, const std::string& fragment,
                   const std::string& label) {
  const std::string problem = box2dPolygonProblem(vertices);
  EXPECT_NE(problem.find(fragment), std::string::npos) << label << ": \"" << problem << "\"";
  // Not through TreeDef::polygon (it needs a polygon with area): a raw tree, as Python could hand
  // the world.
  TreeDef raw;
  raw.shape = TreeShape::polygon;
  raw.vertices = vertices;
  EXPECT_FALSE(builds(raw)) << label;
}

struct Placement {
  double scale, angle;
  Vec2 offset;
};

// Beyond 10⁶ m floats are 0.0625 m apart or more: rounding may turn one fault into another, so
// only the refusal is asserted there, not its words.
std::string unlessFar(const Placement& p, const std::string& fragment) {
  return p.offset.norm() > 1e6 ? "" : fragment;
}

std::vector<Placement> placements() {
  std::vector<Placement> out;
  for (double scale : {1.0, 37.0, 1000.0})
    for (double angle : {0.0, 0.3, 1.9})
      for (const Vec2& offset : {Vec2(0, 0), Vec2(5e3, -2e3), Vec2(9e5, 9e5), Vec2(-4e6, 3e6)})
        out.push_back({scale, angle, offset});
  return out;
}

TEST(Box2dLimits, TheLibraryShapesAreAccepted) {
  for (int n = 3; n <= 8; ++n) {
    for (const Placement& p : placements()) {
      const std::vector<Vec2> v = placed(regular(n, 1.0), p.scale, p.angle, p.offset);
      EXPECT_EQ(box2dPolygonProblem(v), "") << n << " at " << p.offset.transpose();
      EXPECT_TRUE(builds(TreeDef::polygon(v)));
    }
  }
}

TEST(Box2dLimits, SliversNarrowerThanTheLinearSlopAreRefused) {
  for (double width : {0.0049, 1e-4, 1e-9}) {
    for (const Placement& p : placements()) {
      // A thin triangle and a thin quadrilateral, `width` across at their widest: refused as a
      // vertex off its neighbours' line by less than the slop, as too narrow, or as welded.
      expectRefused(placed({{0, 0}, {10, 0}, {5, width}}, 1.0, p.angle, p.offset), "expected",
                    "triangle");
      expectRefused(placed({{0, 0}, {10, 0}, {10, width}, {0, width}}, 1.0, p.angle, p.offset),
                    "expected", "quad");
    }
  }
  // The example: convex, long edges, no collinear triple in double, area 5e-9 m².
  expectRefused({{0, 0}, {10, 0}, {5, 1e-9}}, "", "sliver");
  EXPECT_TRUE(isStrictlyConvex({{0, 0}, {10, 0}, {5, 1e-9}}));
}

TEST(Box2dLimits, CollinearVerticesAreRefusedInDoubleAndAsFloats) {
  for (const Placement& p : placements()) {
    expectRefused(placed({{0, 0}, {1, 0}, {2, 0}, {1, 1}}, p.scale, p.angle, p.offset),
                  unlessFar(p, "in a line"), "collinear");
  }
  // Convex in double, but its middle vertex rounds onto the line as a float (1 m apart at 1e7).
  const std::vector<Vec2> kite{{0, 9e6}, {4, 9e6 + 0.25}, {8, 9e6}, {4, 9e6 - 6}};
  EXPECT_TRUE(isStrictlyConvex(kite));
  expectRefused(kite, "in a line as Box2D's floats", "float");
}

TEST(Box2dLimits, DuplicateAndNearlyDuplicateVerticesAreRefusedNamingThem) {
  for (const Placement& p : placements()) {
    for (double gap : {0.0, 1e-6, 0.0024, 0.049}) {
      std::vector<Vec2> v = placed(regular(6, 2.0), p.scale, p.angle, p.offset);
      v.insert(v.begin() + 3, v[2] + Vec2(gap, 0));  // vertex 3 beside vertex 2
      expectRefused(v, unlessFar(p, "vertices 2 and 3"), "gap " + std::to_string(gap));
    }
  }
  // Not neighbours: a polygon that winds twice visits the same points.
  expectRefused({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {4, 0}}, "vertices 0 and 4", "twice");
}

TEST(Box2dLimits, TinyAreaIsRefused) {
  for (double size : {0.03, 1e-3, 1e-7}) {
    for (const Placement& p : placements())
      expectRefused(placed(regular(4, size), 1.0, p.angle, p.offset), "", "tiny");
  }
}

TEST(Box2dLimits, HugeAndNonFiniteExtentsAreRefusedNamingTheVertex) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double far : {1.0000001e7, 1e9, 1e39, 1e300, inf, std::nan("")}) {
    expectRefused({{0, 0}, {far, 0}, {0, 1}}, "vertex 1: expected coordinates within", "far");
    expectRefused({{-far, -far}, {far, -far}, {0, far}}, "vertex 0", "huge");
  }
  TreeDef disc = TreeDef::disc(Vec2(0, 0), 1e300);
  EXPECT_NE(box2dProblem(disc).find("radius"), std::string::npos);
  EXPECT_FALSE(builds(disc));
  disc.radius = 1e-50;  // positive as a double, zero as a float
  EXPECT_FALSE(builds(disc));
  disc.radius = 1e-6;
  EXPECT_TRUE(builds(disc));
  disc.centre = Vec2(inf, 0);
  disc.radius = 1;
  EXPECT_FALSE(builds(disc));
}

TEST(Box2dLimits, TooFewOrTooManyVerticesAreRefused) {
  for (int n : {0, 1, 2, 9, 12, 100}) {
    expectRefused(n >= 3 ? regular(n, 5.0) : std::vector<Vec2>(n, Vec2(1, 1)),
                  "expected 3 to 8 vertices", std::to_string(n));
  }
}

// Random convex polygons of 3 to 8 vertices, at every scale from a millimetre to a kilometre and
// every offset up to the limit, squashed by up to 10⁶: whatever is accepted, Box2D builds.
TEST(Box2dLimits, EveryAcceptedRandomPolygonBuilds) {
  std::mt19937_64 rng(34);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int accepted = 0, refused = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const int n = 3 + static_cast<int>(unit(rng) * 6);
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) angles.push_back(2.0 * std::numbers::pi * unit(rng));
    std::sort(angles.begin(), angles.end());
    const double scale = std::pow(10.0, -3.0 + 6.0 * unit(rng));
    const double squash = std::pow(10.0, -6.0 * unit(rng));
    const Vec2 offset(std::pow(10.0, 7.0 * unit(rng)) * (unit(rng) < 0.5 ? -1 : 1),
                      std::pow(10.0, 7.0 * unit(rng)) * (unit(rng) < 0.5 ? -1 : 1));
    std::vector<Vec2> v;
    for (double a : angles) v.push_back(offset + scale * Vec2(std::cos(a), squash * std::sin(a)));
    if (box2dPolygonProblem(v).empty()) {
      ++accepted;
      EXPECT_TRUE(builds(TreeDef::polygon(v)));
    } else {
      ++refused;
    }
  }
  // Both sides of the limit are exercised.
  EXPECT_GT(accepted, 1000);
  EXPECT_GT(refused, 1000);
}

}  // namespace
}  // namespace canopy::world
