#pragma once
// Building outlines as surveyed carry vertices a wall cannot use: doubled points, points a few
// millimetres apart, and points on a straight wall. cleanRing drops them so that what is left is
// a polygon world::simplePolygonProblem accepts whenever the outline itself is simple.
#include <vector>

#include "core/types.h"

namespace canopy::gis {

/// Vertices closer than this (m) to the one kept before them are dropped (world::kMinPolygonEdge).
constexpr double kRingWeld = 0.05;
/// A vertex closer than this (m) to the line through its neighbours is dropped: twice Box2D's
/// linear slop, so that the survivors clear the slop after rounding to the millimetre.
constexpr double kRingStraight = 0.01;

/// Repeats until nothing changes: drop a vertex within kRingWeld of the previous kept one, or
/// within kRingStraight of the chord of its neighbours. Fewer than 3 vertices may remain.
std::vector<Vec2> cleanRing(std::vector<Vec2> ring);

/// The ring counter-clockwise, starting at its least vertex (by x, then y): the same outline
/// however a format stores it (a Shapefile keeps outer rings clockwise).
std::vector<Vec2> canonicalRing(std::vector<Vec2> ring);

}  // namespace canopy::gis
