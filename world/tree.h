#pragma once
// Tree occluders (SOO): a crown that hides what is under it. Exact geometry in double; Box2D
// only supplies candidates.
#include <limits>
#include <string>
#include <vector>

#include "core/types.h"

namespace canopy::world {

enum class TreeShape { disc, polygon };

/// One tree crown: a disc (centre, radius) or a convex polygon (counter-clockwise vertices).
/// What stops a ground robot is its solid part: a disc tree's trunk, a disc of trunk_radius at
/// its centre; a polygon is a wall, solid throughout, unless it has a trunk_radius > 0 (then a
/// crown with a trunk at its centroid). Crowns never stop anything.
struct TreeDef {
  TreeShape shape = TreeShape::disc;
  Vec2 centre = Vec2::Zero();  // m; for a polygon, its area centroid
  double radius = 1.0;         // m; for a polygon, the radius of the disc of equal area
  std::vector<Vec2> vertices;  // polygon only, counter-clockwise, convex, 3..8 vertices (m)
  double trunk_radius = 0.1;   // m; disc() sets defaultTrunkRadius(radius), polygon() 0 (a wall)
  // Height (issue 53): the crown (a wall) fills its outline from `base` to `top` above the ground
  // (m), a vertical prism; by default from the ground to above any UAV.
  double base = 0.0;
  double top = std::numeric_limits<double>::infinity();

  static TreeDef disc(const Vec2& centre, double radius);
  /// vertices: convex, either orientation; stored counter-clockwise with centroid and radius set.
  static TreeDef polygon(std::vector<Vec2> vertices);
};

/// The trunk of a crown of radius r when a scenario gives none: 0.1 r, clamped to [0.05, 0.5] m
/// (and never above r).
double defaultTrunkRadius(double crown_radius);

/// True when the whole polygon is solid (a polygon without a trunk).
inline bool isWall(const TreeDef& tree) {
  return tree.shape == TreeShape::polygon && !(tree.trunk_radius > 0.0);
}

/// The distance from p to the tree's solid part (a wall's polygon or the trunk's disc): ≤ 0
/// inside it (then minus the depth for a trunk, 0 for a wall's interior). Exact, in double.
double solidDistance(const TreeDef& tree, const Vec2& p);
/// The distance from the segment a → b to the tree's solid part: 0 when it enters a wall, the
/// distance to the trunk's rim (≤ 0 when it enters the trunk) otherwise. Exact, in double.
double solidDistance(const TreeDef& tree, const Vec2& a, const Vec2& b);

/// True when p is strictly inside the crown (a point on its rim is not hidden).
bool strictlyInside(const TreeDef& tree, const Vec2& p);

/// The fraction s ∈ [0, 1] of the segment a → b at which it first enters the crown's interior,
/// or a negative number when the segment does not cross the interior (touching the rim does not
/// count). s = 0 when a is inside.
double segmentEntry(const TreeDef& tree, const Vec2& a, const Vec2& b);

/// True when the crown's volume (its outline from base to top) hides the point (b, hb) from the
/// point (a, ha), heights in m above the ground: the segment between them passes through the
/// prism's interior. Its ground projection crosses the outline's interior on fractions
/// [s_in, s_out] of a → b (a vertical segment: all of it when a lies strictly inside), over which
/// the height runs linearly from h(s_in) to h(s_out); hidden when that height range meets the
/// open interval (base, top).
bool blocksSight(const TreeDef& tree, const Vec2& a, double ha, const Vec2& b, double hb);

/// The smallest axis-aligned box holding the crown.
Aabb bounds(const TreeDef& tree);

/// Signed area of a polygon (positive when counter-clockwise).
double signedArea(const std::vector<Vec2>& vertices);

/// True when the polygon is strictly convex (no three collinear vertices) in either orientation.
bool isStrictlyConvex(const std::vector<Vec2>& vertices);

/// Coordinates a crown may reach, m: Box2D keeps positions as floats, one metre apart at 1e7.
constexpr double kMaxTreeCoordinate = 1e7;
/// The most vertices of one convex polygon: Box2D's b2_maxPolygonVertices (tree.cpp checks).
constexpr std::size_t kMaxPolygonVertices = 8;
/// Shortest polygon edge, m: ten times Box2D's linear slop (it welds vertices within half of it).
constexpr double kMinPolygonEdge = 0.05;

/// Why Box2D could not take this crown as it is — "" when it can. Box2D (world.cpp) receives the
/// vertices as floats and asserts (aborting the process) on a polygon it cannot build; this runs
/// its checks first, on the same floats: 3 to b2_maxPolygonVertices vertices, every coordinate
/// finite and within ±kMaxTreeCoordinate, strictly convex in double and as floats (Box2D's own
/// gift-wrapping hull keeps every vertex), every edge at least kMinPolygonEdge, and the polygon
/// at least b2_linearSlop wide (a sliver's float area falls under Box2D's epsilon). A disc needs
/// a centre within the limit and a radius in (0, kMaxTreeCoordinate] that is positive as a float.
/// The answer names the vertex or edge at fault ("vertices 2 and 3 …").
std::string box2dProblem(const TreeDef& tree);
/// The same for a polygon given by its vertices in either orientation.
std::string box2dPolygonProblem(const std::vector<Vec2>& vertices);

}  // namespace canopy::world
