#pragma once
// The outlines a frame draws, in metres (pure): a track's 2-σ ellipse, a footprint's outline and
// the part of a ground robot's sector that the crowns leave visible. buildScene draws them
// (scene_builder.h); rendered coverage fills the footprints (coverage.h).
#include <vector>

#include "core/types.h"
#include "sensing/footprint.h"
#include "world/tree.h"

namespace canopy::render {

/// The points of the 2-σ ellipse of a position covariance P (m²) around `centre`: the level set
/// (p − c)ᵀ P⁻¹ (p − c) = 4, as `points` vertices counter-clockwise. Empty when P is not finite.
std::vector<Vec2> covarianceEllipse(const Vec2& centre, const Mat2& P, int points = 36);

/// The corners of a rectangular footprint; for a sector its apex, then points along its arc no
/// more than 1° apart; an empty list for a disc. Star-shaped from its first point either way.
std::vector<Vec2> footprintCorners(const sensing::Footprint& footprint);

/// What a ground robot's sector camera sees past the crowns: the sector's outline with each arc
/// point pulled back along its ray from the apex to where the ray first enters a crown.
std::vector<Vec2> visibleSector(const sensing::Footprint& sector,
                                const std::vector<world::TreeDef>& trees);

}  // namespace canopy::render
