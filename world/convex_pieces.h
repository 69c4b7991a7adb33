#pragma once
// Walls of any shape: a simple polygon (any number of vertices, concave allowed, no crossing
// edges) cut into convex pieces that Box2D can take (b2_maxPolygonVertices each). Every part of
// canopy then sees the same pieces — Box2D bodies, occlusion ray casts, sensing, the agents' maps,
// planning, frames and the replay — because the scenario loader hands the world the pieces as
// ordinary convex polygon walls.
//
// Method: ear clipping into triangles (at each step the ear whose smallest angle is largest, so
// that thin slivers are avoided where the polygon allows), then Hertel–Mehlhorn merging: a
// diagonal between two pieces is removed when the union is still strictly convex, has at most
// max_vertices vertices and passes box2dPolygonProblem(). Hertel–Mehlhorn gives at most four
// times the fewest convex pieces (without the vertex limit).
#include <string>
#include <vector>

#include "core/types.h"
#include "world/tree.h"

namespace canopy::world {

/// The most vertices a wall polygon may have (the decomposition is O(n²)).
constexpr std::size_t kMaxWallVertices = 1024;

/// Why the vertices do not form a simple polygon — "" when they do: at least 3 finite vertices,
/// no two closer than kMinPolygonEdge, no two edges that cross or touch other than neighbours at
/// their shared vertex, no vertex within b2_linearSlop of the line through its neighbours, and a
/// non-zero area. The answer names the vertices or edges at fault (0-based).
std::string simplePolygonProblem(const std::vector<Vec2>& vertices);

/// The polygon (simple, either orientation) as convex pieces, each counter-clockwise with 3 to
/// max_vertices vertices, together covering it exactly. Throws std::invalid_argument with a
/// message naming the piece when a piece cannot be made that Box2D takes (a sliver).
std::vector<std::vector<Vec2>> convexPieces(const std::vector<Vec2>& vertices,
                                            std::size_t max_vertices = kMaxPolygonVertices);

}  // namespace canopy::world
